#include "ArgParser.h"

#include <cmath>

namespace lk::lkctl {

void ArgParser::addOption(const QString &name, bool takesValue)
{
    m_declared.insert(name, takesValue);
}

bool ArgParser::looksNumeric(const QString &word)
{
    if (word.size() < 2 || word.at(0) != QLatin1Char('-'))
        return false;
    const QChar c = word.at(1);
    return c.isDigit() || c == QLatin1Char('.');
}

bool ArgParser::parse(const QStringList &args, QString *error)
{
    m_values.clear();
    m_positionals.clear();
    bool optionsEnded = false;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (optionsEnded || !a.startsWith(QLatin1Char('-')) || a == QLatin1String("-") ||
            looksNumeric(a)) {
            m_positionals.append(a);
            continue;
        }
        if (a == QLatin1String("--")) {
            optionsEnded = true;
            continue;
        }
        QString name = a.startsWith(QLatin1String("--")) ? a.mid(2) : a.mid(1);
        std::optional<QString> inlineValue;
        if (const auto eq = name.indexOf(QLatin1Char('=')); eq >= 0) {
            inlineValue = name.mid(eq + 1);
            name.truncate(eq);
        }
        const auto it = m_declared.constFind(name);
        if (it == m_declared.cend() || !a.startsWith(QLatin1String("--"))) {
            *error = QStringLiteral("unknown option '%1'").arg(a);
            return false;
        }
        if (m_values.contains(name)) {
            *error = QStringLiteral("--%1 given twice").arg(name);
            return false;
        }
        if (!it.value()) {
            if (inlineValue) {
                *error = QStringLiteral("--%1 takes no value").arg(name);
                return false;
            }
            m_values.insert(name, QString());
            continue;
        }
        if (inlineValue) {
            m_values.insert(name, *inlineValue);
        } else if (i + 1 < args.size() && (!args.at(i + 1).startsWith(QLatin1String("--")) ||
                                           looksNumeric(args.at(i + 1)))) {
            m_values.insert(name, args.at(++i));
        } else {
            *error = QStringLiteral("--%1 needs a value").arg(name);
            return false;
        }
    }
    return true;
}

std::optional<qint64> ArgParser::intValue(const QString &name, qint64 min, qint64 max,
                                          QString *error) const
{
    bool ok = false;
    const qint64 v = value(name).toLongLong(&ok);
    if (!ok || v < min || v > max) {
        *error = QStringLiteral("--%1 must be an integer in %2..%3 (got '%4')")
                     .arg(name)
                     .arg(min)
                     .arg(max)
                     .arg(value(name));
        return std::nullopt;
    }
    return v;
}

std::optional<double> ArgParser::numberValue(const QString &name, double min, QString *error) const
{
    bool ok = false;
    const double v = value(name).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < min) {
        *error = QStringLiteral("--%1 must be a number >= %2 (got '%3')")
                     .arg(name)
                     .arg(min)
                     .arg(value(name));
        return std::nullopt;
    }
    return v;
}

} // namespace lk::lkctl
