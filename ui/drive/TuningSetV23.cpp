#include "TuningSetV23.h"

#include "TuningText.h"

#include <protocol/RequestBuilder.h>

#include <limits>

namespace lk::ui {

namespace {
constexpr int kGainMax = 255;

std::optional<protocol::PidGains> heldPid(const HeldValues &held)
{
    for (int i = TuningSetV23::AngleKp; i <= TuningSetV23::IqKi; ++i) {
        if (!held.value(i))
            return std::nullopt;
    }
    ParamValues v;
    for (int i = TuningSetV23::AngleKp; i <= TuningSetV23::IqKi; ++i)
        v << *held.at(i);
    v << 0;
    return TuningSetV23::pidOf(v);
}
} // namespace

QVector<ParamField> TuningSetV23::fields() const
{
    const QString gainTip = QCoreApplication::translate("lk::ui::ParameterTable", "0..255");
    auto gain = [&](const char *key, const QString &name, TunedLoop loop) {
        return ParamField{QLatin1String(key), name, loop, 0, kGainMax, 0, QString(), gainTip};
    };
    ParamField accel{
        QStringLiteral("accel_dps2"),
        QCoreApplication::translate("lk::ui::ParameterTable", "Acceleration"),
        TunedLoop::Speed, // acceleration shapes the speed ramp
        0,
        std::numeric_limits<qint32>::max(),
        0,
        QCoreApplication::translate("lk::ui::ParameterTable", " dps/s"),
        QCoreApplication::translate("lk::ui::ParameterTable",
                                    "0x34 writes acceleration to RAM only: protocol V2.3 has no "
                                    "ROM command for it. Some firmware ignores it (read back "
                                    "shows)."),
        1000};
    return {gain("angle_kp", QCoreApplication::translate("lk::ui::ParameterTable", "Angle loop Kp"),
                 TunedLoop::Angle),
            gain("angle_ki", QCoreApplication::translate("lk::ui::ParameterTable", "Angle loop Ki"),
                 TunedLoop::Angle),
            gain("speed_kp", QCoreApplication::translate("lk::ui::ParameterTable", "Speed loop Kp"),
                 TunedLoop::Speed),
            gain("speed_ki", QCoreApplication::translate("lk::ui::ParameterTable", "Speed loop Ki"),
                 TunedLoop::Speed),
            gain("iq_kp", QCoreApplication::translate("lk::ui::ParameterTable", "Current loop Kp"),
                 TunedLoop::Current),
            gain("iq_ki", QCoreApplication::translate("lk::ui::ParameterTable", "Current loop Ki"),
                 TunedLoop::Current),
            accel};
}

ParamSetTexts TuningSetV23::texts() const
{
    // Worded where the view used to word them (their translations stay).
    return {
        QCoreApplication::translate("lk::ui::TuningView", "PID gains and acceleration"),
        QCoreApplication::translate(
            "lk::ui::TuningView",
            "Gains go to RAM (try: lost at power-off) or ROM (keep). Acceleration is RAM "
            "only: protocol V2.3 has no command that stores it."),
        QCoreApplication::translate("lk::ui::TuningView", "read_pid (0x30) and read_accel (0x33)"),
        QCoreApplication::translate(
            "lk::ui::TuningView",
            "Try the pending edit: 0x31 and 0x34, lost at power-off; read back."),
        QCoreApplication::translate("lk::ui::TuningView",
                                    "Keep the gains: 0x32 writes flash (asks first); read back.")};
}

QVector<protocol::Request> TuningSetV23::reads(int id) const
{
    return {*protocol::build::plain(protocol::Command::ReadPid, id).request,
            *protocol::build::plain(protocol::Command::ReadAccel, id).request};
}

HeldValues TuningSetV23::decode(const QVector<protocol::Reply> &replies) const
{
    HeldValues held(kFieldCount);
    for (const protocol::Reply &r : replies) {
        if (const auto *pid = std::get_if<protocol::PidGains>(&r.payload)) {
            const ParamValues v = valuesOf(*pid, 0);
            for (int i = AngleKp; i <= IqKi; ++i)
                held[i] = v.at(i);
        } else if (const auto *a = std::get_if<protocol::Acceleration>(&r.payload)) {
            held[Accel] = a->dps2;
        }
    }
    return held;
}

QVector<ParamWrite> TuningSetV23::writes(int id, const ParamValues &values, const ParamValues &held,
                                         bool rom) const
{
    QVector<ParamWrite> out;
    out << ParamWrite{protocol::build::writePid(id, pidOf(values), rom),
                      {AngleKp, AngleKi, SpeedKp, SpeedKi, IqKp, IqKi}};
    if (values.at(Accel) != held.at(Accel)) // RAM only, and only when it changes
        out << ParamWrite{protocol::build::writeAcceleration(id, values.at(Accel)), {Accel}};
    return out;
}

QString TuningSetV23::valuesText(const ParamValues &values) const
{
    return TuningText::tr("Gains %1 (angle, speed, iq Kp/Ki), acceleration %2 dps/s.")
        .arg(TuningText::gains(pidOf(values)))
        .arg(values.at(Accel));
}

ConfirmRequest TuningSetV23::romQuestion(int id, const ParamValues &values) const
{
    return TuningText::romWrite(id, pidOf(values));
}

QStringList TuningSetV23::readBackProblems(const SentValues &sent, const HeldValues &held) const
{
    TuningWrite w;
    w.rom = sent.rom;
    w.pid = pidOf(sent.values);
    if (sent.fields.contains(Accel))
        w.accelDps2 = static_cast<qint32>(sent.values.at(Accel));
    const std::optional<qint64> accel = held.value(Accel);
    return TuningText::readBackProblems(
        w, heldPid(held), accel ? std::optional<qint32>(qint32(*accel)) : std::nullopt,
        known(held).has_value());
}

QString TuningSetV23::written(const SentValues &sent, int id) const
{
    TuningWrite w;
    w.rom = sent.rom;
    return TuningText::written(w, id);
}

bool TuningSetV23::toFile(const HeldValues &held, record::ParameterSet &set) const
{
    const std::optional<protocol::PidGains> pid = heldPid(held);
    if (!pid)
        return false;
    set.generation = generation();
    set.pid = *pid;
    const std::optional<qint64> accel = held.value(Accel);
    set.accelDps2 = accel ? std::optional<qint32>(qint32(*accel)) : std::nullopt;
    return true;
}

std::optional<ParamValues> TuningSetV23::fromFile(const record::ParameterSet &set,
                                                  const ParamValues &current) const
{
    return valuesOf(set.pid, set.accelDps2.value_or(qint32(current.value(Accel))));
}

protocol::PidGains TuningSetV23::pidOf(const ParamValues &v)
{
    auto g = [&](int i) { return static_cast<quint8>(v.at(i)); };
    return protocol::PidGains{g(AngleKp), g(AngleKi), g(SpeedKp), g(SpeedKi), g(IqKp), g(IqKi)};
}

ParamValues TuningSetV23::valuesOf(const protocol::PidGains &p, qint32 accelDps2)
{
    return {p.angleKp, p.angleKi, p.speedKp, p.speedKi, p.iqKp, p.iqKi, accelDps2};
}

} // namespace lk::ui
