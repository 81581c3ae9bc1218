#pragma once

#include "FleetCatalog.h"

#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QMap>
#include <QtCore/QMetaType>
#include <QtCore/QString>

#include <optional>

namespace lk::fleet {

/// Who a drive is: as its read_model reply says (RS485), or as the user declared it where no
/// model read exists (CAN: series, generation and gear; names and versions stay unknown).
struct DriveIdentity {
    int id = 0;
    QString driverName; ///< empty and meaningless when `declared`
    QString motorName;
    std::optional<protocol::Series> series; ///< nullopt: the model names none
    /// On CAN, V2_3 is the old CAN generation and V2_35 CAN V2.36 (docs/CAN.md section 3).
    protocol::Generation generation = protocol::Generation::V2_3;
    quint16 hardwareRaw = 0; ///< as on the wire (V2.3 / 10, V2.35 / 100); unknown if declared
    quint16 firmwareRaw = 0;
    QByteArray uniqueId; ///< V2.35's 12-byte motor ID; empty on V2.3, which has none
    protocol::Link link = protocol::Link::Rs485;
    /// The user's word, not a model read: the drive speaks CAN, which has no read_model (0x12).
    bool declared = false;
    std::optional<double> gearRatio; ///< declared with the identity; nullopt: not given
};

/// One value as read: the wire value and when its reply arrived (UTC).
struct ReadValue {
    qint64 value = 0;
    QDateTime readAt;
};

/// What one read of a drive's parameters gave: its identity (when read_model answered, or the
/// user declared it on CAN), the
/// values that were read, and why the rest were not. A value not read is absent, never 0.
struct DriveSnapshot {
    DriveIdentity identity;
    bool identified = false; ///< read_model answered, or (CAN) the identity was declared
    QString failure;         ///< empty when every parameter of the generation was read
    QDateTime readAt;        ///< when the read of this drive started (UTC)
    QMap<QString, ReadValue> values;

    int id() const { return identity.id; }
    /// Every parameter of the drive's generation was read.
    bool complete() const
    {
        if (!identified)
            return false;
        for (const FleetParam &p : FleetCatalog::params(identity.generation, identity.link)) {
            if (!values.contains(p.key))
                return false;
        }
        return true;
    }
    ValueMap valueMap() const
    {
        ValueMap out;
        for (auto it = values.begin(); it != values.end(); ++it)
            out.insert(it.key(), it.value().value);
        return out;
    }
};

} // namespace lk::fleet

Q_DECLARE_METATYPE(lk::fleet::DriveSnapshot)
