#include "TuningSetCan236.h"

#include <protocol/RequestBuilder.h>

#include <limits>

namespace lk::ui {

using protocol::ControlParameter;
using protocol::ControlParamId;

namespace {
constexpr qint64 kGainMax = 65535;
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr int kGroups = 8; ///< three PIDs, five one-number parameters
constexpr int kFirstValue = 9;

ParamField valueField(const char *key, const QString &name, TunedLoop loop, qint64 max,
                      int decimals, const QString &suffix, const QString &tip)
{
    ParamField f;
    f.key = QLatin1String(key);
    f.name = name;
    f.loop = loop;
    f.max = max;
    f.decimals = decimals;
    f.suffix = suffix;
    f.tip = tip;
    return f;
}
} // namespace

ControlParamId TuningSetCan236::paramOf(int group)
{
    static constexpr ControlParamId kParams[kGroups] = {
        ControlParamId::AnglePid,         ControlParamId::SpeedPid,
        ControlParamId::CurrentPid,       ControlParamId::InputTorqueLimit,
        ControlParamId::InputSpeedLimit,  ControlParamId::InputAngleLimit,
        ControlParamId::InputCurrentRamp, ControlParamId::InputSpeedRamp};
    return kParams[group];
}

QVector<int> TuningSetCan236::fieldsOf(int group)
{
    if (group < 3)
        return {3 * group, 3 * group + 1, 3 * group + 2};
    return {kFirstValue + group - 3};
}

QString TuningSetCan236::ramOnlyReason()
{
    return tr("CAN V2.36 keeps these in RAM only: they are lost at power-off.");
}

QVector<ParamField> TuningSetCan236::fields() const
{
    const QString tip = tr("0..65535, raw gain (CAN V2.36 control parameters 0x0A..0x0C)");
    const QString loops[] = {tr("Angle loop"), tr("Speed loop"), tr("Current loop")};
    const TunedLoop loopOf[] = {TunedLoop::Angle, TunedLoop::Speed, TunedLoop::Current};
    const char *keys[] = {"angle", "speed", "iq"};
    const char *gains[] = {"kp", "ki", "kd"};
    QVector<ParamField> out;
    for (int l = 0; l < 3; ++l) {
        for (int g = 0; g < 3; ++g) {
            const QString gain = QString::fromLatin1(gains[g]);
            ParamField f;
            f.key = QStringLiteral("%1_%2").arg(QLatin1String(keys[l]), gain);
            f.name = QStringLiteral("%1 %2").arg(loops[l], gain.at(0).toUpper() + gain.mid(1));
            f.loop = loopOf[l];
            f.max = kGainMax;
            f.tip = tip;
            out << f;
        }
    }
    // Units as CAN.md infers them from the RS485 tool; the current ramp's is unknown.
    out << valueField("max_torque", tr("Input torque limit"), TunedLoop::Current, 2048, 0,
                      tr(" (of 2048)"), tr("0x1E, iq units, 2048 = full scale (inferred)"));
    out << valueField("max_speed_dps", tr("Input speed limit"), TunedLoop::Speed, kInt32Max, 2,
                      tr(" dps"), tr("0x20, 0.01 dps on the wire (inferred)"));
    out << valueField("max_angle_deg", tr("Input angle limit"), TunedLoop::Angle, kInt32Max, 2,
                      tr(" deg"), tr("0x22, 0.01 deg on the wire (inferred)"));
    out << valueField("current_ramp_raw", tr("Input current ramp (unit unknown)"),
                      TunedLoop::Current, kInt32Max, 0, QString(),
                      tr("0x24: the raw number; the CAN V2.36 document gives no unit"));
    out << valueField("speed_ramp_dps2", tr("Input speed ramp"), TunedLoop::Speed, kInt32Max, 0,
                      tr(" dps/s"), tr("0x26, dps/s (inferred)"));
    return out;
}

ParamSetTexts TuningSetCan236::texts() const
{
    return {tr("Control parameters (CAN V2.36)"),
            tr("Read with 0xC0 and written with 0xC1 to RAM: effective at once, lost at "
               "power-off. ") +
                ramOnlyReason(),
            tr("read_control_param (0xC0) for IDs 0x0A..0x0C and 0x1E..0x26"),
            tr("Write the changed values: 0xC1, RAM only, lost at power-off; read back."),
            ramOnlyReason()};
}

QVector<protocol::Request> TuningSetCan236::reads(int id) const
{
    QVector<protocol::Request> out;
    for (int g = 0; g < kGroups; ++g)
        out << *protocol::build::readControlParam(id, paramOf(g)).request;
    return out;
}

HeldValues TuningSetCan236::decode(const QVector<protocol::Reply> &replies) const
{
    HeldValues held(kFieldCount);
    for (const protocol::Reply &r : replies) {
        const auto *v = std::get_if<ControlParameter>(&r.payload);
        for (int g = 0; v && g < kGroups; ++g) {
            if (v->id() != paramOf(g))
                continue;
            const QVector<int> f = fieldsOf(g);
            if (f.size() == 3) {
                for (int i = 0; i < 3; ++i)
                    held[f.at(i)] = v->pid()[size_t(i)];
            } else {
                held[f.at(0)] = v->value();
            }
        }
    }
    return held;
}

QVector<ParamWrite> TuningSetCan236::writes(int id, const ParamValues &values,
                                            const ParamValues &held, bool rom) const
{
    QVector<ParamWrite> out;
    if (rom) { // no command stores them: refused, nothing sent
        protocol::BuildResult refused;
        refused.error =
            protocol::FieldError{QStringLiteral("rom"), QStringLiteral("RAM"), ramOnlyReason()};
        out << ParamWrite{refused, {}};
        return out;
    }
    for (int g = 0; g < kGroups; ++g) {
        const QVector<int> f = fieldsOf(g);
        bool changed = false;
        for (int i : f)
            changed = changed || values.value(i) != held.value(i);
        if (!changed)
            continue;
        const ControlParameter v =
            f.size() == 3
                ? ControlParameter::ofPid(paramOf(g), quint16(values.at(f.at(0))),
                                          quint16(values.at(f.at(1))), quint16(values.at(f.at(2))))
                : ControlParameter::ofValue(paramOf(g), qint32(values.at(f.at(0))));
        out << ParamWrite{protocol::build::writeControlParam(id, v), f};
    }
    return out;
}

QString TuningSetCan236::valuesText(const ParamValues &v) const
{
    QVector<int> all;
    for (int i = 0; i < kFieldCount; ++i)
        all << i;
    return fieldsText(v, all);
}

ConfirmRequest TuningSetCan236::romQuestion(int, const ParamValues &) const
{
    // Never asked: writes() refuses ROM. Worded for completeness of the interface.
    ConfirmRequest q;
    q.key = QStringLiteral("write_control_param_rom");
    q.title = tr("No ROM on CAN V2.36");
    q.question = ramOnlyReason();
    return q;
}

QString TuningSetCan236::written(const SentValues &, int id) const
{
    return tr("Written to the RAM of drive %1 (0xC1) and read back with 0xC0: the drive holds "
              "what was sent. ")
               .arg(id) +
           ramOnlyReason();
}

bool TuningSetCan236::toFile(const HeldValues &held, record::ParameterSet &set) const
{
    for (int i = 0; i < 9; ++i) {
        if (!held.value(i))
            return false;
    }
    set.generation = generation();
    for (int i = 0; i < 9; ++i)
        set.pidV235[std::size_t(i)] = static_cast<quint16>(*held.at(i));
    set.accelDps2.reset();
    return true;
}

std::optional<ParamValues> TuningSetCan236::fromFile(const record::ParameterSet &set,
                                                     const ParamValues &current) const
{
    if (current.size() != kFieldCount)
        return std::nullopt;
    ParamValues values = current; // the limits are not in files: they stay as shown
    for (int i = 0; i < 9; ++i)
        values[i] = set.pidV235[std::size_t(i)];
    return values;
}

} // namespace lk::ui
