#include "WireEncoding.h"

#include <QtCore/QCoreApplication>

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
                                         const safety::SoftLimits *limits, bool seriesKnown)
{
    if (limits && request.command == protocol::Command::Speed) {
        // The torque limit's raw value depends on the series' iq scale: a drive whose series
        // nobody gave would get a limit at MF's scale, twice the current on an MG.
        const auto *c = std::get_if<protocol::SpeedCommand>(&request.payload);
        if (c && !c->iqLimitRaw && context.onCan() &&
            context.generation == protocol::Generation::V2_35 && !seriesKnown) {
            protocol::WireEncodeResult refused;
            refused.error.field = QStringLiteral("series");
            refused.error.range = QStringLiteral("MS, MF, MG or MH");
            refused.error.problem = QCoreApplication::translate(
                "lk::bus::WireEncoding",
                "not known: a CAN V2.36 speed command carries a torque limit scaled by it");
            return refused;
        }
        addSpeedTorqueLimit(request, context, *limits);
    }
    return protocol::encodeRequest(request, context);
}

} // namespace lk::bus
