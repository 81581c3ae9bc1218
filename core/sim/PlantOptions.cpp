#include "PlantOptions.h"

#include <QtCore/QStringList>

#include <cmath>

namespace lk::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;

bool fail(QString *error, const QString &text)
{
    if (error)
        *error = text;
    return false;
}

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}
} // namespace

std::optional<PlantOptions> PlantOptions::parse(const QString &text, QString *error)
{
    PlantOptions out;
    for (const QString &item : text.split(QLatin1Char('+'), Qt::SkipEmptyParts))
        if (!out.parseItem(item.trimmed(), error))
            return std::nullopt;
    return out;
}

bool PlantOptions::isItem(const QString &item)
{
    const QString key = item.section(QLatin1Char('='), 0, 0).trimmed().toLower();
    return item.contains(QLatin1Char('=')) &&
           (key == QLatin1String("resonance") || key == QLatin1String("counts") ||
            key == QLatin1String("speed-res") || key == QLatin1String("friction"));
}

bool PlantOptions::parseItem(const QString &item, QString *error)
{
    const qsizetype eq = item.indexOf(QLatin1Char('='));
    const QString key = item.left(eq).trimmed().toLower();
    const QString value = eq < 0 ? QString() : item.mid(eq + 1).trimmed();
    if (key == QLatin1String("resonance")) {
        const QStringList parts = value.split(QLatin1Char('/'));
        const auto hz = number(parts.value(0));
        const auto damping = parts.size() > 1 ? number(parts[1]) : std::optional<double>(0.05);
        const auto ratio = parts.size() > 2 ? number(parts[2]) : std::optional<double>(1);
        if (parts.size() > 3 || !hz || *hz < kMinResonanceHz || *hz > kMaxResonanceHz)
            return fail(error, QStringLiteral("\"%1\": the resonance must be %2..%3 Hz "
                                              "(resonance=HZ[/DAMPING[/LOAD_RATIO]])")
                                   .arg(item)
                                   .arg(kMinResonanceHz)
                                   .arg(kMaxResonanceHz));
        if (!damping || *damping <= 0 || *damping > 2)
            return fail(error,
                        QStringLiteral("\"%1\": the damping ratio must be above 0 and at most 2")
                            .arg(item));
        if (!ratio || *ratio < 0.05 || *ratio > 20)
            return fail(error, QStringLiteral("\"%1\": the load ratio must be 0.05..20").arg(item));
        resonance = MechanicalResonance{*hz, *damping, *ratio};
        return true;
    }
    if (key == QLatin1String("counts")) {
        bool ok = false;
        const int counts = value.toInt(&ok);
        if (!ok || counts < 16 || counts > (1 << 24))
            return fail(error, QStringLiteral("\"%1\": the counts per turn must be 16..%2")
                                   .arg(item)
                                   .arg(1 << 24));
        sensor.countsPerTurn = counts;
        return true;
    }
    if (key == QLatin1String("speed-res")) {
        const auto dps = number(value);
        if (!dps || *dps <= 0 || *dps > 100)
            return fail(error,
                        QStringLiteral("\"%1\": the speed resolution must be above 0 and at most "
                                       "100 dps")
                            .arg(item));
        sensor.speedResolutionDps = *dps;
        return true;
    }
    if (key == QLatin1String("friction")) {
        const auto nm = number(value);
        if (!nm || *nm < 0 || *nm > kMaxFrictionNm)
            return fail(error, QStringLiteral("\"%1\": the Coulomb friction must be 0..%2 Nm")
                                   .arg(item)
                                   .arg(kMaxFrictionNm));
        coulombFrictionNm = *nm;
        return true;
    }
    return fail(error, QStringLiteral("\"%1\": unknown plant option (resonance=, counts=, "
                                      "speed-res=, friction=)")
                           .arg(item));
}

QString PlantOptions::toString() const
{
    QStringList items;
    if (resonance.enabled())
        items << QStringLiteral("resonance=%1/%2/%3")
                     .arg(resonance.hz)
                     .arg(resonance.damping)
                     .arg(resonance.loadRatio);
    if (sensor.countsPerTurn > 0)
        items << QStringLiteral("counts=%1").arg(sensor.countsPerTurn);
    if (sensor.speedResolutionDps > 0)
        items << QStringLiteral("speed-res=%1").arg(sensor.speedResolutionDps);
    if (coulombFrictionNm)
        items << QStringLiteral("friction=%1").arg(*coulombFrictionNm);
    return items.join(QLatin1Char('+'));
}

TwoMassMechanics::TwoMassMechanics(double inertia, double viscous,
                                   const MechanicalResonance &resonance)
    : j1(inertia), b(viscous)
{
    if (!resonance.enabled())
        return;
    // The motor's and the load's inertia add up to the rotor's; the motor side's peak is at
    // w = sqrt(k (1/J1 + 1/J2)), i.e. k = w^2 Jr with Jr = J1 J2 / (J1 + J2).
    j1 = inertia / (1 + resonance.loadRatio);
    j2 = inertia - j1;
    const double w = 2 * kPi * resonance.hz;
    const double reduced = j1 * j2 / inertia;
    k = w * w * reduced;
    c = 2 * resonance.damping * w * reduced;
}

TwoMassMechanics::State TwoMassMechanics::step(const State &x, double torque, double dt) const
{
    State n;
    const double spring = k * x.twist;
    const double a11 = j1 / dt + c + b;
    const double r1 = j1 / dt * x.motor + torque - spring;
    if (j2 <= 0) {
        n.motor = r1 / a11;
        return n;
    }
    const double a22 = j2 / dt + c;
    const double r2 = j2 / dt * x.load + spring;
    const double det = a11 * a22 - c * c;
    n.motor = (r1 * a22 + c * r2) / det;
    n.load = (a11 * r2 + c * r1) / det;
    n.twist = x.twist + dt * (n.motor - n.load);
    return n;
}

} // namespace lk::sim
