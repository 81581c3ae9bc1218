#include "ParamSetSpec.h"

#include <cmath>

namespace lk::ui {

QString ParamSetSpec::shown(const ParamField &field, qint64 value)
{
    const QString number =
        field.decimals == 0
            ? QString::number(value)
            : QString::number(double(value) / std::pow(10.0, field.decimals), 'f', field.decimals);
    return number + field.suffix;
}

std::optional<ParamValues> ParamSetSpec::known(const HeldValues &held)
{
    ParamValues values;
    values.reserve(held.size());
    for (const std::optional<qint64> &v : held) {
        if (!v)
            return std::nullopt;
        values << *v;
    }
    return values;
}

QString ParamSetSpec::fieldsText(const ParamValues &values, const QVector<int> &which) const
{
    const QVector<ParamField> f = fields();
    QStringList parts;
    for (int i : which) {
        if (i < f.size() && i < values.size())
            parts << QStringLiteral("%1 %2").arg(f.at(i).name, shown(f.at(i), values.at(i)));
    }
    return parts.join(QStringLiteral(", "));
}

QString ParamSetSpec::valuesText(const ParamValues &values) const
{
    QVector<int> all;
    for (int i = 0; i < values.size(); ++i)
        all << i;
    return fieldsText(values, all);
}

bool ParamSetSpec::toFile(const HeldValues &, record::ParameterSet &) const
{
    return false;
}

std::optional<ParamValues> ParamSetSpec::fromFile(const record::ParameterSet &,
                                                  const ParamValues &) const
{
    return std::nullopt;
}

QStringList ParamSetSpec::readBackProblems(const SentValues &sent, const HeldValues &held) const
{
    const QVector<ParamField> f = fields();
    QStringList problems;
    bool complete = true;
    for (int i : sent.fields) {
        if (i >= held.size() || !held.at(i)) {
            complete = false;
            continue;
        }
        if (*held.at(i) != sent.values.at(i))
            problems << tr("%1: the drive holds %2 after %3 was written.")
                            .arg(f.at(i).name, shown(f.at(i), *held.at(i)),
                                 shown(f.at(i), sent.values.at(i)));
    }
    if (!complete || !known(held))
        problems << tr("The read-back did not complete: what the drive holds is not known. "
                       "Editing and writing stay off until Read from drive succeeds.");
    return problems;
}

} // namespace lk::ui
