#pragma once

#include <protocol/Series.h>

#include <QtCore/QMetaType>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {

/// What the user says a drive is, where no model read tells it (CAN, listen-only RS485):
/// BusSession::setDriveIdentity. On CAN, Generation::V2_3 is the old CAN generation and
/// V2_35 CAN V2.36 (docs/CAN.md section 3).
struct DriveIdentity {
    int id = 0;
    protocol::Series series = protocol::Series::MF;
    protocol::Generation generation = protocol::Generation::V2_3;
    std::optional<double> gearRatio;

    /// "ID:SERIES@GEN[/GEAR]": `3:MG@2.35`, `1:MF@can236`, `2:MS@can`, `4:MG@2.3/36`. GEN is
    /// 2.3 or 2.35 (RS485), can or can-old (the old CAN generation), can236 or 2.36 (CAN
    /// V2.36); the generation is required: a drive is never decoded by a guess. nullopt with
    /// `error` naming the part that is wrong.
    static std::optional<DriveIdentity> parse(const QString &text, QString *error);
    /// A comma-separated list of parse()'s form; each ID once.
    static std::optional<QVector<DriveIdentity>> parseList(const QString &text, QString *error);
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::DriveIdentity)
