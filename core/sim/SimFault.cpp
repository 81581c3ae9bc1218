#include "SimFault.h"

#include "protocol/ErrorFlags.h"

namespace lk::sim {

namespace {

constexpr int kMotorOverTemperatureBit = 3;

std::optional<int> bitOf(const QString &name, protocol::Generation generation)
{
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::of(generation)) {
        if (name == QLatin1String(f.key))
            return f.bit;
    }
    // Bit 3 is "over_temperature" on V2.3 and "motor_over_temperature" on V2.35: the V2.3 word
    // names it on both, as the example in lksim --help does.
    if (name == QLatin1String("over_temperature"))
        return kMotorOverTemperatureBit;
    return std::nullopt;
}

/// "5", "5s", "2.5s": seconds, not negative.
std::optional<double> seconds(QString text)
{
    text = text.trimmed();
    if (text.endsWith(QLatin1Char('s'), Qt::CaseInsensitive))
        text.chop(1);
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !(v >= 0) || !qIsFinite(v))
        return std::nullopt;
    return v;
}

QString secondsText(double s)
{
    return QString::number(s, 'g', 10) + QLatin1Char('s');
}

} // namespace

QStringList SimFault::names(protocol::Generation generation)
{
    QStringList out;
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::of(generation))
        out << QLatin1String(f.key);
    return out;
}

std::optional<SimFault> SimFault::parse(const QString &text, protocol::Generation generation,
                                        QString *error)
{
    auto fail = [error](const QString &message) -> std::optional<SimFault> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QString trimmed = text.trimmed();
    const qsizetype at = trimmed.indexOf(QLatin1Char('@'));
    const QString name = (at < 0 ? trimmed : trimmed.left(at)).trimmed().toLower();
    const std::optional<int> bit = bitOf(name, generation);
    if (!bit)
        return fail(QStringLiteral("unknown fault '%1' for a %2 drive (known: %3)")
                        .arg(name, protocol::generationName(generation),
                             names(generation).join(QStringLiteral(", "))));
    SimFault f;
    f.bit = *bit;
    if (at < 0)
        return f;
    const QString when = trimmed.mid(at + 1);
    const qsizetype dash = when.indexOf(QLatin1Char('-'));
    const std::optional<double> start = seconds(dash < 0 ? when : when.left(dash));
    const std::optional<double> end = dash < 0 ? std::nullopt : seconds(when.mid(dash + 1));
    if (!start || (dash >= 0 && (!end || *end <= *start)))
        return fail(QStringLiteral("'%1': the time must be @START or @START-END in seconds "
                                   "(e.g. @5s, @2-4.5s), END after START")
                        .arg(trimmed));
    f.startS = *start;
    f.endS = end;
    return f;
}

QString SimFault::toString(protocol::Generation generation) const
{
    QString name;
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::of(generation)) {
        if (f.bit == bit)
            name = QLatin1String(f.key);
    }
    if (startS == 0 && !endS)
        return name;
    QString text = name + QLatin1Char('@') + secondsText(startS);
    if (endS)
        text += QLatin1Char('-') + secondsText(*endS);
    return text;
}

} // namespace lk::sim
