#include "HeardMultiTorque.h"

#include <protocol/CanLayout.h>
#include <protocol/Values.h>

namespace lk::bus {

namespace can = protocol::can;

std::optional<QVector<HeardMultiTorque::Slot>>
HeardMultiTorque::decode(const protocol::CanRecord &record, const ContextOf &contextOf)
{
    if (record.canId != can::kMultiMotorId || record.isExtended() || record.isEcho() ||
        record.isError())
        return std::nullopt;
    const auto iq = can::decodeMultiMotorTorque(record.canData());
    if (!iq)
        return std::nullopt;
    QVector<Slot> out;
    for (int slot = 0; slot < can::kMultiMotorDrives; ++slot) {
        const int id = slot + 1;
        const std::optional<protocol::DecodeContext> context = contextOf(id);
        if (!context || context->generation != protocol::Generation::V2_3)
            continue;
        protocol::DecodeContext c = *context;
        c.link = protocol::Link::Can;
        protocol::Request request;
        request.command = protocol::Command::Torque;
        request.id = quint8(id);
        protocol::TorqueCommand torque;
        torque.iqRaw = (*iq)[size_t(slot)];
        torque.ampsPerLsb = protocol::iqCommandAmpsPerLsb(c);
        request.payload = torque;
        const can::CanEncodeResult data = can::encodeRequest(request, c);
        const std::optional<protocol::Frame> frame =
            data.data ? can::frameOf(*data.data) : std::nullopt;
        if (frame)
            out.append({request, *frame});
    }
    return out;
}

} // namespace lk::bus
