#include "Series.h"

namespace lk::protocol {

QString seriesName(Series s)
{
    switch (s) {
    case Series::MS:
        return QStringLiteral("MS");
    case Series::MF:
        return QStringLiteral("MF");
    case Series::MG:
        return QStringLiteral("MG");
    case Series::MH:
        return QStringLiteral("MH");
    }
    return QString();
}

std::optional<Series> seriesFromName(const QString &name)
{
    const QString n = name.trimmed().toUpper();
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        if (n == seriesName(s))
            return s;
    }
    return std::nullopt;
}

} // namespace lk::protocol
