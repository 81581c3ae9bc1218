#include "LinkCodec.h"

#include "CanLayout.h"
#include "CanRecord.h"

namespace lk::protocol {

namespace {
WireEncodeResult fromCan(const can::CanEncodeResult &r)
{
    WireEncodeResult out;
    if (r.ok())
        out.bytes = CanRecord::of(*r.data).encode();
    else
        out.error = r.error;
    return out;
}
} // namespace

WireEncodeResult encodeRequest(const Request &request, const DecodeContext &context)
{
    if (context.link == Link::Can)
        return fromCan(can::encodeRequest(request, context));
    return WireEncodeResult{request.encode(), {}};
}

WireEncodeResult encodeReply(const Reply &reply, const DecodeContext &context)
{
    if (context.link == Link::Can)
        return fromCan(can::encodeReply(reply, context));
    return WireEncodeResult{reply.encode(), {}};
}

} // namespace lk::protocol
