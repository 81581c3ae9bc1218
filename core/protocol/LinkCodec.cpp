#include "LinkCodec.h"

#include "CanLayout.h"
#include "CanRecord.h"

#include <QtCore/QCoreApplication>

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
/// 0xC0/0xC1 exist on CAN V2.36 only: an RS485 drive would stay silent.
WireEncodeResult notOnRs485(Command command, const DecodeContext &context)
{
    WireEncodeResult out;
    out.error = FieldError{
        QStringLiteral("command"), dialectName(context),
        QCoreApplication::translate("lk::protocol::LinkCodec", "%1 exists on CAN V2.36 only")
            .arg(CommandTable::name(command))};
    return out;
}
} // namespace

WireEncodeResult encodeRequest(const Request &request, const DecodeContext &context)
{
    if (context.link == Link::Can)
        return fromCan(can::encodeRequest(request, context));
    // A 0x95 with an angle is CAN V2.36's; RS485's 0x95 only zeroes.
    if (CommandTable::info(request.command).canOnly ||
        std::holds_alternative<PositionSet>(request.payload))
        return notOnRs485(request.command, context);
    return WireEncodeResult{request.encode(), {}};
}

WireEncodeResult encodeReply(const Reply &reply, const DecodeContext &context)
{
    if (context.link == Link::Can)
        return fromCan(can::encodeReply(reply, context));
    if (CommandTable::info(reply.command).canOnly)
        return notOnRs485(reply.command, context);
    return WireEncodeResult{reply.encode(), {}};
}

} // namespace lk::protocol
