#pragma once

#include "DriveIdentity.h"

#include <protocol/Series.h>
#include <protocol/Values.h>

#include <QtCore/QMap>
#include <QtCore/QMetaType>

#include <optional>

namespace lk::bus {

/// What the bus knows about one ID: from a scan, from setSeries, or from replies.
/// Callers use `series` to check support (e.g. no torque or read_state3 on MS) and to pass
/// every motion request through the soft-limit check before BusSession::send.
struct KnownMotor {
    int id = 0;
    std::optional<protocol::Series> series; ///< nullopt: unknown, decoded as MF (iq)
    protocol::Generation generation = protocol::Generation::V2_3;
    std::optional<protocol::ModelInfo> model; ///< from read_model, when it answered
    /// The user chose series and generation (BusSession::setDriveIdentity): a drive without a
    /// model read (CAN, listen-only) decodes by it, and no reply overrides it.
    bool identityChosen = false;
    /// The generation was told by a reply (CAN: the reply ID or the 0x9A layout).
    bool generationSeen = false;
    std::optional<double> gearRatio; ///< the user's, when given (CAN cannot read it)
    /// Whether the generation is known: read from the model, chosen, or seen in a reply.
    bool generationKnown() const { return model.has_value() || identityChosen || generationSeen; }
};

using KnownMotors = QMap<int, KnownMotor>;

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::KnownMotors)
