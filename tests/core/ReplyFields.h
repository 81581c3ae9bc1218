#pragma once

#include "protocol/Reply.h"

#include <QtCore/QStringList>
#include <QtCore/QVariantMap>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace lk::test {

/// Every field of a typed reply as a map with CLI.md names (plus _raw and a "kind"), so that
/// table rows can state expectations in physical units and compare whole replies.
namespace proto = lk::protocol;

struct Fields {
    QVariantMap m;
    void operator()(const proto::Acknowledged &) { m[QStringLiteral("kind")] = "ack"; }
    void operator()(const proto::PidGains &g)
    {
        m[QStringLiteral("kind")] = "pid";
        m[QStringLiteral("angle_kp")] = g.angleKp;
        m[QStringLiteral("angle_ki")] = g.angleKi;
        m[QStringLiteral("speed_kp")] = g.speedKp;
        m[QStringLiteral("speed_ki")] = g.speedKi;
        m[QStringLiteral("iq_kp")] = g.iqKp;
        m[QStringLiteral("iq_ki")] = g.iqKi;
    }
    void operator()(const proto::Acceleration &a)
    {
        m[QStringLiteral("kind")] = "accel";
        m[QStringLiteral("accel_dps2")] = a.dps2;
    }
    void operator()(const proto::EncoderReading &e)
    {
        m[QStringLiteral("kind")] = "encoder";
        m[QStringLiteral("encoder")] = e.encoder;
        m[QStringLiteral("encoder_raw")] = e.encoderRaw;
        m[QStringLiteral("encoder_offset")] = e.encoderOffset;
    }
    void operator()(const proto::EncoderOffset &o)
    {
        m[QStringLiteral("kind")] = "offset";
        m[QStringLiteral("encoder_offset")] = o.offset;
    }
    void operator()(const proto::ZeroWritten &z)
    {
        m[QStringLiteral("kind")] = "zero";
        m[QStringLiteral("has_offset")] = z.encoderOffset.has_value();
        if (z.encoderOffset)
            m[QStringLiteral("encoder_offset")] = *z.encoderOffset;
    }
    void operator()(const proto::MultiTurnAngle &a)
    {
        m[QStringLiteral("kind")] = "multi_turn";
        m[QStringLiteral("angle_raw")] = qlonglong(a.raw);
        m[QStringLiteral("angle_deg")] = a.degrees();
    }
    void operator()(const proto::SingleTurnAngle &a)
    {
        m[QStringLiteral("kind")] = "single_turn";
        m[QStringLiteral("angle_raw")] = qlonglong(a.raw);
        m[QStringLiteral("angle_deg")] = a.degrees();
    }
    void operator()(const proto::State1 &s)
    {
        m[QStringLiteral("kind")] = "state1";
        m[QStringLiteral("temperature_c")] = s.temperatureC;
        m[QStringLiteral("voltage_raw")] = s.voltageRaw;
        m[QStringLiteral("voltage_v")] = s.voltageV();
        m[QStringLiteral("error_state")] = s.errorState;
        m[QStringLiteral("low_voltage")] = s.lowVoltage();
        m[QStringLiteral("over_temperature")] = s.overTemperature();
    }
    void operator()(const proto::State2 &s)
    {
        m[QStringLiteral("kind")] = "state2";
        m[QStringLiteral("temperature_c")] = s.temperatureC;
        m[QStringLiteral("is_power")] = s.isPower;
        if (s.isPower) {
            m[QStringLiteral("power")] = s.torqueRaw;
        } else {
            m[QStringLiteral("iq_raw")] = s.torqueRaw;
            m[QStringLiteral("iq_a")] = s.iqA();
        }
        m[QStringLiteral("speed_dps")] = s.speedDps;
        m[QStringLiteral("encoder")] = s.encoder;
    }
    void operator()(const proto::State3 &s)
    {
        m[QStringLiteral("kind")] = "state3";
        m[QStringLiteral("temperature_c")] = s.temperatureC;
        m[QStringLiteral("ia_raw")] = s.iaRaw;
        m[QStringLiteral("ib_raw")] = s.ibRaw;
        m[QStringLiteral("ic_raw")] = s.icRaw;
        m[QStringLiteral("ia_a")] = s.iaA();
        m[QStringLiteral("ib_a")] = s.ibA();
        m[QStringLiteral("ic_a")] = s.icA();
    }
    void operator()(const proto::ModelInfo &i)
    {
        const bool v23 = i.generation == proto::Generation::V2_3;
        m[QStringLiteral("kind")] = "model";
        m[QStringLiteral("driver_name")] = i.driverName;
        m[QStringLiteral("motor_name")] = i.motorName;
        m[QStringLiteral("hardware_raw")] = i.hardwareRaw;
        m[QStringLiteral("firmware_raw")] = i.firmwareRaw;
        m[QStringLiteral("hardware_version")] = i.hardwareVersion();
        m[QStringLiteral("firmware_version")] = i.firmwareVersion();
        m[QStringLiteral("generation")] = v23 ? "V2.3" : "V2.35";
        if (!v23) {
            m[QStringLiteral("motor_id")] = QString::fromLatin1(i.motorId);
            m[QStringLiteral("motor_version_raw")] = i.motorVersionRaw;
        }
    }
    void operator()(const proto::ParameterValue &v)
    {
        m[QStringLiteral("kind")] = "parameter";
        m[QStringLiteral("param_id")] = v.paramId;
        m[QStringLiteral("value_i32")] = v.asInt32();
    }
    void operator()(const proto::ParamWriteResult &r)
    {
        m[QStringLiteral("kind")] = "param_write";
        m[QStringLiteral("param_id")] = r.paramId;
        m[QStringLiteral("flag")] = r.flag;
    }
    void operator()(const proto::BrakeState &b)
    {
        m[QStringLiteral("kind")] = "brake";
        m[QStringLiteral("brake_raw")] = b.raw;
    }
    void operator()(const proto::ControlParameter &v)
    {
        m[QStringLiteral("kind")] = "control_param";
        m[QStringLiteral("param_id")] = v.paramId;
        m[QStringLiteral("value_i32")] = v.value();
    }
};

inline QVariantMap fields(const proto::Reply &r)
{
    Fields f;
    std::visit(f, r.payload);
    f.m[QStringLiteral("id")] = r.id;
    return f.m;
}

inline bool sameValue(const QVariant &a, const QVariant &b)
{
    if (a.typeId() == QMetaType::Double || b.typeId() == QMetaType::Double) {
        const double x = a.toDouble(), y = b.toDouble();
        return std::fabs(x - y) <= 1e-9 * std::max(1.0, std::fabs(y));
    }
    if (a.typeId() == QMetaType::QString || b.typeId() == QMetaType::QString ||
        a.typeId() == QMetaType::Bool || b.typeId() == QMetaType::Bool)
        return a.toString() == b.toString();
    return a.toLongLong() == b.toLongLong();
}

/// Every expected key is present with the expected value; with `exact`, no other key exists.
inline QString mismatch(const QVariantMap &actual, const QVariantMap &expected, bool exact)
{
    for (auto it = expected.cbegin(); it != expected.cend(); ++it) {
        if (!actual.contains(it.key()))
            return QStringLiteral("missing %1").arg(it.key());
        if (!sameValue(actual.value(it.key()), it.value()))
            return QStringLiteral("%1: got %2, want %3")
                .arg(it.key(), actual.value(it.key()).toString(), it.value().toString());
    }
    if (exact && actual.size() != expected.size())
        return QStringLiteral("extra keys: got %1").arg(QStringList(actual.keys()).join(u' '));
    return {};
}

inline QVariantMap map(std::initializer_list<std::pair<const char *, QVariant>> kv)
{
    QVariantMap m;
    for (const auto &[k, v] : kv)
        m.insert(QString::fromLatin1(k), v);
    return m;
}

} // namespace lk::test
