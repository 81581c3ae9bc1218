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
        const qint16 iqRaw = (*iq)[size_t(slot)];
        protocol::Request request;
        request.command = protocol::Command::Torque;
        request.id = quint8(id);
        protocol::TorqueCommand torque;
        torque.iqRaw = iqRaw;
        torque.ampsPerLsb = protocol::iqCommandAmpsPerLsb(c);
        request.payload = torque;
        // The 0xA1 as the drive takes it, built here rather than by the encoder: the encoder
        // refuses a value beyond +-2000 that we would not send, but another master may, and
        // its drive still answers it.
        QByteArray bytes(8, '\0');
        bytes[0] = char(quint8(protocol::Command::Torque));
        bytes[4] = char(quint16(iqRaw) & 0xFF);
        bytes[5] = char(quint16(iqRaw) >> 8);
        const std::optional<protocol::Frame> frame =
            can::frameOf({can::requestCanId(quint8(id)), bytes});
        if (frame)
            out.append({request, *frame});
    }
    return out;
}

} // namespace lk::bus
