#include "TuningSetV235.h"

#include <protocol/RequestBuilder.h>

namespace lk::ui {

namespace {
constexpr qint64 kGainMax = 65535;
} // namespace

QVector<ParamField> TuningSetV235::fields() const
{
    const QString tip = tr("0..65535, raw gain (V2.35 ParamIDs 0x96..0x98)");
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
    return out;
}

ParamSetTexts TuningSetV235::texts() const
{
    return {tr("PID gains (protocol V2.35)"),
            tr("Gains go to RAM (0x42, try: lost at power-off) or ROM (0x44, keep). No "
               "acceleration here: V2.35 has no 0x33/0x34, its current and speed ramps are in "
               "the drive limits."),
            tr("read_param (0x40) for ParamIDs 0x96, 0x97 and 0x98"),
            tr("Try the pending edit: 0x42, lost at power-off; read back."),
            tr("Keep the gains: 0x44 writes flash (asks first); read back.")};
}

QVector<protocol::Request> TuningSetV235::reads(int id) const
{
    QVector<protocol::Request> out;
    for (protocol::ParamId p : kLoops)
        out << *protocol::build::readParam(id, p).request;
    return out;
}

HeldValues TuningSetV235::decode(const QVector<protocol::Reply> &replies) const
{
    HeldValues held(kFieldCount);
    for (const protocol::Reply &r : replies) {
        const auto *v = std::get_if<protocol::ParameterValue>(&r.payload);
        for (int l = 0; v && l < 3; ++l) {
            if (v->id() != kLoops[l])
                continue;
            held[3 * l] = v->pidKp();
            held[3 * l + 1] = v->pidKi();
            held[3 * l + 2] = v->pidKd();
        }
    }
    return held;
}

QVector<ParamWrite> TuningSetV235::writes(int id, const ParamValues &values, const ParamValues &,
                                          bool rom) const
{
    // Every loop is written, changed or not: a ROM write then stores the whole set shown.
    QVector<ParamWrite> out;
    for (int l = 0; l < 3; ++l)
        out << ParamWrite{protocol::build::writeParamPid(id, kLoops[l], values.at(3 * l),
                                                         values.at(3 * l + 1), values.at(3 * l + 2),
                                                         rom),
                          {3 * l, 3 * l + 1, 3 * l + 2}};
    return out;
}

QString TuningSetV235::valuesText(const ParamValues &v) const
{
    return tr("angle %1/%2/%3, speed %4/%5/%6, current %7/%8/%9 (Kp/Ki/Kd)")
        .arg(v.at(0))
        .arg(v.at(1))
        .arg(v.at(2))
        .arg(v.at(3))
        .arg(v.at(4))
        .arg(v.at(5))
        .arg(v.at(6))
        .arg(v.at(7))
        .arg(v.at(8));
}

ConfirmRequest TuningSetV235::romQuestion(int id, const ParamValues &values) const
{
    ConfirmRequest q;
    q.key = QStringLiteral("write_param_rom");
    q.title = tr("Write gains to ROM");
    q.question =
        tr("Write these PID gains to the ROM of drive %1?\n%2").arg(id).arg(valuesText(values));
    q.reason = tr("ROM is the drive's flash memory: each write wears it, and the gains stay "
                  "after power-off. Try them in RAM first; write to ROM once you are satisfied. "
                  "Each loop is sent once with 0x44 (never retried), then all gains are read "
                  "back with 0x40.");
    q.acceptText = tr("Write to ROM");
    return q;
}

QString TuningSetV235::written(const SentValues &sent, int id) const
{
    if (sent.rom)
        return tr("Written to the ROM of drive %1 (0x44, acknowledged) and read back with 0x40: "
                  "the drive holds what was sent.")
            .arg(id);
    return tr("Written to the RAM of drive %1 and read back: the drive holds what was sent. Lost "
              "at power-off unless written to ROM.")
        .arg(id);
}

bool TuningSetV235::toFile(const HeldValues &held, record::ParameterSet &set) const
{
    const std::optional<ParamValues> values = known(held);
    if (!values)
        return false;
    set.generation = generation();
    for (int i = 0; i < kFieldCount; ++i)
        set.pidV235[std::size_t(i)] = static_cast<quint16>(values->at(i));
    set.accelDps2.reset();
    return true;
}

std::optional<ParamValues> TuningSetV235::fromFile(const record::ParameterSet &set,
                                                   const ParamValues &) const
{
    ParamValues values;
    for (quint16 v : set.pidV235)
        values << v;
    return values;
}

} // namespace lk::ui
