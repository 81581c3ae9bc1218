#pragma once

#include <protocol/Parameter.h>

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QVector>

namespace lk::record {

/// The JSON fields of V2.35 parameters as lkctl (`info`, `read ID params`) and the bus report
/// name them (docs/CLI.md): a loop's Kp, Ki, Kd as angle_kp ... iq_kd, a value under its field
/// name with its raw integer, and the max angle joined from its two halves (max_angle_deg,
/// max_angle_raw).
class ParameterFields {
public:
    /// One parameter read: one value, or the max angle's two halves (0x9B, then 0x9C).
    static QJsonObject of(const QList<protocol::ParameterValue> &values);
    /// Every parameter of `values` (as read, any order; the max angle needs both halves),
    /// the loops' gains into `pid`, the others into `params`.
    static void split(const QVector<protocol::ParameterValue> &values, QJsonObject &pid,
                      QJsonObject &params);
};

} // namespace lk::record
