#include "FleetCatalog.h"

#include <motor/SeriesLimits.h>
#include <protocol/ControlParameter.h>
#include <protocol/Parameter.h>
#include <protocol/ProtocolFields.h>
#include <protocol/RequestBuilder.h>

#include <limits>

namespace lk::fleet {

namespace {

using protocol::ControlParameter;
using protocol::ControlParamId;
using protocol::FieldId;
using protocol::Generation;
using protocol::Link;
using protocol::ParameterValue;
using protocol::ParamId;

constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr qint64 kEncoderMax = 65535;
const char *const kAngleLow = "max_angle_low"; // decode()'s halves until joinHalves()
const char *const kAngleHigh = "max_angle_high";

const char *const kGainsV23[] = {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"};
const char *const kLoops[] = {"angle", "speed", "iq"};
const ParamId kLoopIds[] = {ParamId::AnglePid, ParamId::SpeedPid, ParamId::CurrentPid};

/// The V2.35 one-value parameters: key (wire units), ParamID, the protocol field whose range
/// the request builder enforces.
struct LimitParam {
    const char *key;
    ParamId id;
    FieldId field;
};
const LimitParam kLimits[] = {
    {"max_torque", ParamId::MaxTorqueCurrent, FieldId::MaxTorque},
    {"max_speed_raw", ParamId::MaxSpeed, FieldId::ParamMaxSpeedDps},
    {"max_angle_raw", ParamId::MaxAngleLow, FieldId::MaxAngleDeg},
    {"current_ramp", ParamId::CurrentRamp, FieldId::CurrentRamp},
    {"speed_ramp_dps2", ParamId::SpeedRamp, FieldId::SpeedRampDps2},
};

/// The CAN V2.36 one-number control parameters (docs/CAN.md 4.1): key (wire units), ID, the
/// largest value CAN.md section 3 allows (none is negative).
struct ControlLimit {
    const char *key;
    ControlParamId id;
    qint64 max;
};
const ControlLimit kControlLimits[] = {
    {"max_torque", ControlParamId::InputTorqueLimit, 2048},
    {"max_speed_raw", ControlParamId::InputSpeedLimit, kInt32Max},
    {"max_angle_raw", ControlParamId::InputAngleLimit, kInt32Max},
    {"current_ramp_raw", ControlParamId::InputCurrentRamp, kInt32Max},
    {"speed_ramp_dps2", ControlParamId::InputSpeedRamp, kInt32Max},
};
const ControlParamId kControlLoops[] = {ControlParamId::AnglePid, ControlParamId::SpeedPid,
                                        ControlParamId::CurrentPid};

QString loopKey(int loop, const char *gain)
{
    return QStringLiteral("%1_%2").arg(QLatin1String(kLoops[loop]), QLatin1String(gain));
}

FleetParam encoderOffset()
{
    return {QStringLiteral("encoder_offset"), 0, kEncoderMax, false, false};
}

ParameterValue limitValue(const LimitParam &p, qint64 raw, bool high = false)
{
    if (p.id == ParamId::MaxAngleLow)
        return ParameterValue::maxAngleHalf(raw, high);
    if (protocol::ParamTable::info(p.id).layout == protocol::ParamLayout::Int16)
        return ParameterValue::int16(p.id, static_cast<qint16>(raw));
    return ParameterValue::int32(p.id, static_cast<qint32>(raw));
}

protocol::Request writeRequest(int id, bool rom, const ParameterValue &value)
{
    return protocol::Request{rom ? protocol::Command::WriteParamRom
                                 : protocol::Command::WriteParamRam,
                             static_cast<quint8>(id), value};
}

bool anyOf(const QStringList &changed, const QStringList &keys)
{
    for (const QString &k : keys) {
        if (changed.contains(k))
            return true;
    }
    return false;
}

QVector<ParamFrame> writesV23(int id, const ValueMap &v, const QStringList &changed, bool rom)
{
    QVector<ParamFrame> out;
    QStringList gains;
    for (const char *k : kGainsV23)
        gains << QLatin1String(k);
    if (rom || anyOf(changed, gains)) {
        auto g = [&](int i) { return int(v.value(gains.at(i))); };
        out << ParamFrame{
            *protocol::build::writePid(id, g(0), g(1), g(2), g(3), g(4), g(5), rom).request, gains};
    }
    const QString accel = QStringLiteral("accel_dps2");
    if (!rom && changed.contains(accel))
        out << ParamFrame{*protocol::build::writeAcceleration(id, v.value(accel)).request, {accel}};
    return out;
}

QVector<ParamFrame> writesV235(int id, const ValueMap &v, const QStringList &changed, bool rom)
{
    QVector<ParamFrame> out;
    for (int l = 0; l < 3; ++l) {
        const QStringList keys{loopKey(l, "kp"), loopKey(l, "ki"), loopKey(l, "kd")};
        if (!rom && !anyOf(changed, keys))
            continue;
        auto g = [&](int i) { return static_cast<quint16>(v.value(keys.at(i))); };
        out << ParamFrame{writeRequest(id, rom, ParameterValue::pid(kLoopIds[l], g(0), g(1), g(2))),
                          keys};
    }
    for (const LimitParam &p : kLimits) {
        const QString key = QLatin1String(p.key);
        if (!rom && !changed.contains(key))
            continue;
        out << ParamFrame{writeRequest(id, rom, limitValue(p, v.value(key))), {key}};
        if (p.id == ParamId::MaxAngleLow) // the int64 is a pair: low, then high
            out << ParamFrame{writeRequest(id, rom, limitValue(p, v.value(key), true)), {key}};
    }
    return out;
}

/// RAM only: CAN V2.36 has no ROM write for its control parameters.
QVector<ParamFrame> writesCan236(int id, const ValueMap &v, const QStringList &changed)
{
    QVector<ParamFrame> out;
    for (int l = 0; l < 3; ++l) {
        const QStringList keys{loopKey(l, "kp"), loopKey(l, "ki"), loopKey(l, "kd")};
        if (!anyOf(changed, keys))
            continue;
        auto g = [&](int i) { return static_cast<quint16>(v.value(keys.at(i))); };
        const ControlParameter value = ControlParameter::ofPid(kControlLoops[l], g(0), g(1), g(2));
        out << ParamFrame{*protocol::build::writeControlParam(id, value).request, keys};
    }
    for (const ControlLimit &c : kControlLimits) {
        const QString key = QLatin1String(c.key);
        if (!changed.contains(key))
            continue;
        const ControlParameter value =
            ControlParameter::ofValue(c.id, static_cast<qint32>(v.value(key)));
        out << ParamFrame{*protocol::build::writeControlParam(id, value).request, {key}};
    }
    return out;
}

} // namespace

const QVector<FleetParam> &FleetCatalog::params(Generation generation, Link link)
{
    static const QVector<FleetParam> can236 = [] {
        QVector<FleetParam> out;
        for (int l = 0; l < 3; ++l) {
            for (const char *g : {"kp", "ki", "kd"})
                out << FleetParam{loopKey(l, g), 0, 65535, true, true};
        }
        for (const ControlLimit &c : kControlLimits)
            out << FleetParam{QLatin1String(c.key), 0, c.max, true, true};
        out << encoderOffset();
        return out;
    }();
    if (isCan236(generation, link))
        return can236;
    static const QVector<FleetParam> v23 = [] {
        QVector<FleetParam> out;
        for (const char *k : kGainsV23)
            out << FleetParam{QLatin1String(k), 0, 255};
        out << FleetParam{QStringLiteral("accel_dps2"), 0, kInt32Max, true, true};
        out << encoderOffset();
        return out;
    }();
    static const QVector<FleetParam> v235 = [] {
        QVector<FleetParam> out;
        for (int l = 0; l < 3; ++l) {
            for (const char *g : {"kp", "ki", "kd"})
                out << FleetParam{loopKey(l, g), 0, 65535};
        }
        for (const LimitParam &p : kLimits) {
            const protocol::ProtocolField &f = protocol::ProtocolFields::field(p.field);
            out << FleetParam{QLatin1String(p.key), f.min, f.max};
        }
        out << encoderOffset();
        return out;
    }();
    return generation == Generation::V2_3 ? v23 : v235;
}

std::optional<FleetParam> FleetCatalog::find(Generation generation, const QString &key, Link link)
{
    for (const FleetParam &p : params(generation, link)) {
        if (p.key == key)
            return p;
    }
    return std::nullopt;
}

bool FleetCatalog::inRange(Generation generation, const QString &key, qint64 value, Link link)
{
    const std::optional<FleetParam> p = find(generation, key, link);
    return p && value >= p->min && value <= p->max;
}

QVector<protocol::Request> FleetCatalog::reads(int id, Generation generation,
                                               std::optional<protocol::Series> series, Link link)
{
    QVector<protocol::Request> out;
    auto add = [&](protocol::Command c) {
        if (!series || motor::supports(*series, c))
            out << *protocol::build::plain(c, id).request;
    };
    if (isCan236(generation, link)) {
        for (const protocol::ControlParamInfo &info : protocol::ControlParamTable::all())
            out << *protocol::build::readControlParam(id, info.id).request;
    } else if (generation == Generation::V2_3) {
        add(protocol::Command::ReadPid);
        add(protocol::Command::ReadAccel);
    } else {
        for (const protocol::ParamInfo &info : protocol::ParamTable::all())
            out << *protocol::build::readParam(id, info.id).request;
    }
    add(protocol::Command::ReadEncoder);
    return out;
}

ValueMap FleetCatalog::decode(const protocol::Reply &reply)
{
    ValueMap out;
    if (const auto *pid = std::get_if<protocol::PidGains>(&reply.payload)) {
        const quint8 g[] = {pid->angleKp, pid->angleKi, pid->speedKp,
                            pid->speedKi, pid->iqKp,    pid->iqKi};
        for (int i = 0; i < 6; ++i)
            out.insert(QLatin1String(kGainsV23[i]), g[i]);
    } else if (const auto *a = std::get_if<protocol::Acceleration>(&reply.payload)) {
        out.insert(QStringLiteral("accel_dps2"), a->dps2);
    } else if (const auto *e = std::get_if<protocol::EncoderReading>(&reply.payload)) {
        out.insert(QStringLiteral("encoder_offset"), e->encoderOffset);
    } else if (const auto *c = std::get_if<ControlParameter>(&reply.payload)) {
        for (int l = 0; l < 3; ++l) {
            if (c->id() == kControlLoops[l]) {
                out.insert(loopKey(l, "kp"), c->pid()[0]);
                out.insert(loopKey(l, "ki"), c->pid()[1]);
                out.insert(loopKey(l, "kd"), c->pid()[2]);
            }
        }
        for (const ControlLimit &cl : kControlLimits) {
            if (c->id() == cl.id)
                out.insert(QLatin1String(cl.key), c->value());
        }
    } else if (const auto *p = std::get_if<ParameterValue>(&reply.payload)) {
        for (int l = 0; l < 3; ++l) {
            if (p->id() == kLoopIds[l]) {
                out.insert(loopKey(l, "kp"), p->pidKp());
                out.insert(loopKey(l, "ki"), p->pidKi());
                out.insert(loopKey(l, "kd"), p->pidKd());
            }
        }
        for (const LimitParam &lp : kLimits) {
            if (p->id() != lp.id || lp.id == ParamId::MaxAngleLow)
                continue;
            const bool int16 =
                protocol::ParamTable::info(lp.id).layout == protocol::ParamLayout::Int16;
            out.insert(QLatin1String(lp.key), int16 ? qint64(p->asInt16()) : p->asInt32());
        }
        // The max angle's halves stay apart until both are there (joinHalves).
        if (p->id() == ParamId::MaxAngleLow)
            out.insert(QLatin1String(kAngleLow), qint64(p->asUInt32()));
        else if (p->id() == ParamId::MaxAngleHigh)
            out.insert(QLatin1String(kAngleHigh), qint64(p->asInt32()));
    }
    return out;
}

void FleetCatalog::joinHalves(ValueMap &values)
{
    const QString low = QLatin1String(kAngleLow);
    const QString high = QLatin1String(kAngleHigh);
    if (values.contains(low) && values.contains(high))
        values.insert(QStringLiteral("max_angle_raw"),
                      qint64(quint64(values.value(high)) << 32 | quint64(values.value(low))));
    values.remove(low);
    values.remove(high);
}

QVector<ParamFrame> FleetCatalog::writes(int id, Generation generation, const ValueMap &values,
                                         const QStringList &changed, bool rom, Link link)
{
    if (isCan236(generation, link))
        return rom ? QVector<ParamFrame>() : writesCan236(id, values, changed);
    return generation == Generation::V2_3 ? writesV23(id, values, changed, rom)
                                          : writesV235(id, values, changed, rom);
}

} // namespace lk::fleet
