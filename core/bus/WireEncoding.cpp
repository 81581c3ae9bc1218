#include "WireEncoding.h"

#include <protocol/RequestBuilder.h>

#include <variant>

namespace lk::bus {

namespace {
void addSpeedTorqueLimit(protocol::Request &r, const protocol::DecodeContext &context,
                         const safety::SoftLimits &limits)
{
    auto *c = std::get_if<protocol::SpeedCommand>(&r.payload);
    if (!c || c->iqLimitRaw || !context.onCan() ||
        context.generation != protocol::Generation::V2_35)
        return;
    const protocol::BuildResult b =
        protocol::build::speed(r.id, c->speedDps(), context, limits.maxTorqueA);
    if (b.ok())
        r = *b.request;
}
} // namespace

protocol::WireEncodeResult encodeForWire(protocol::Request &request,
                                         const protocol::DecodeContext &context,
                                         const safety::SoftLimits *limits)
{
    if (limits && request.command == protocol::Command::Speed)
        addSpeedTorqueLimit(request, context, *limits);
    return protocol::encodeRequest(request, context);
}

} // namespace lk::bus
