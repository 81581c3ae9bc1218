#include "MultiTorque.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>

#include <variant>

namespace lk::bus {

namespace can = protocol::can;

QByteArray encodeMultiTorque(const QVector<protocol::Request> &torques)
{
    std::array<qint16, can::kMultiMotorDrives> iq{};
    std::array<bool, can::kMultiMotorDrives> named{};
    if (torques.isEmpty())
        return {};
    for (const protocol::Request &r : torques) {
        const auto *t = std::get_if<protocol::TorqueCommand>(&r.payload);
        const int slot = r.id - 1;
        if (!t || r.command != protocol::Command::Torque || slot < 0 ||
            slot >= can::kMultiMotorDrives || named[size_t(slot)])
            return {};
        named[size_t(slot)] = true;
        iq[size_t(slot)] = t->iqRaw;
    }
    const can::CanEncodeResult e = can::encodeMultiMotorTorque(iq);
    if (!e.ok())
        return {};
    return protocol::CanRecord::of(*e.data).encode();
}

} // namespace lk::bus
