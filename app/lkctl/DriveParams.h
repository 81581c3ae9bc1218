#pragma once

#include <protocol/FieldJson.h>
#include <protocol/Parameter.h>
#include <protocol/ProtocolFields.h>
#include <protocol/Request.h>

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// One V2.35 setting parameter as lkctl names it (info's `params`, `read ID params`,
/// `write ID param`): a PID loop (angle_pid, with Kp Ki Kd), a one-value parameter under its
/// value field's name (max_speed_dps), or max_angle_deg, the int64 kept in 0x9B and 0x9C.
struct DriveParam {
    QString name;
    QList<protocol::ParamId> ids;      ///< one, or MaxAngleLow then MaxAngleHigh
    QList<protocol::FieldSpec> fields; ///< the values a write takes, in order
    bool isLoop() const { return fields.size() == 3; }
};

/// The V2.35 parameter set, derived from protocol::ParamTable and ProtocolFields' value fields
/// (one source of names): lookup, reading with read_param, and the JSON of a value.
class DriveParams {
public:
    static const QList<DriveParam> &all();
    /// By lkctl name (angle_pid, max_speed_dps, max_angle_deg ...); nullopt otherwise (a
    /// half of max_angle_deg is never written alone).
    static std::optional<DriveParam> find(const QString &name);
    static QString names(); ///< "angle_pid, speed_pid, ..." for help and errors
    /// One help line per parameter: its name, its values and their ranges.
    static QString helpLines(const QString &indent);

    /// Read `param` with read_param (one request per ID); after printing why, nullopt.
    static std::optional<QList<protocol::ParameterValue>> read(LiveBus &bus, int id,
                                                               const DriveParam &param);
    /// Read `param` and add its value fields to `into`; false after printing why.
    static bool readFields(LiveBus &bus, int id, const DriveParam &param, QJsonObject &into);
    /// Read every parameter: loops' gains into `pid`, the others into `params`. False when a
    /// read failed (reported); what was read is kept.
    static bool readAll(LiveBus &bus, int id, QJsonObject &pid, QJsonObject &params);
    /// The reason a V2.3 drive cannot do `what`, naming the V2.3 commands to use instead.
    static QString noTableMessage(int id, const QString &what);
};

} // namespace lk::lkctl
