#pragma once

#include <protocol/CanRecord.h>
#include <protocol/Frame.h>
#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QVector>

#include <functional>
#include <optional>

namespace lk::bus {

/// Another master's multi-motor torque frame (CAN 0x280, docs/CAN.md section 4.2), as a
/// listener or a replay reads it: the torque command it gives each drive it names.
struct HeardMultiTorque {
    /// One slot, as the drive of its ID takes it.
    struct Slot {
        protocol::Request request; ///< Command::Torque, at the drive's current scale
        protocol::Frame frame;     ///< the 0xA1 request it answers as (pairs its reply)
    };
    /// The decode context of a drive seen on the bus, nullopt for an ID nobody has seen.
    using ContextOf = std::function<std::optional<protocol::DecodeContext>(int id)>;

    /// The slots of `record` whose drive `contextOf` knows on the old CAN generation (V2.36
    /// has no such frame; a slot of no drive seen is left out, since nothing tells whether one
    /// is there); a value beyond the +-2000 we send is kept as heard. Nullopt for a record that
    /// is no 0x280 data frame heard on the bus (an echo of our own, an error frame, another
    /// ID, another length).
    static std::optional<QVector<Slot>> decode(const protocol::CanRecord &record,
                                               const ContextOf &contextOf);
};

} // namespace lk::bus
