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

QString generationName(Generation g)
{
    return g == Generation::V2_3 ? QStringLiteral("v2.3") : QStringLiteral("v2.35");
}

std::optional<Generation> generationFromName(const QString &name)
{
    QString n = name.trimmed().toLower();
    if (n.startsWith(QLatin1Char('v')))
        n.remove(0, 1);
    if (n == QLatin1String("2.3"))
        return Generation::V2_3;
    if (n == QLatin1String("2.35"))
        return Generation::V2_35;
    return std::nullopt;
}

QString linkName(Link l)
{
    return l == Link::Can ? QStringLiteral("can") : QStringLiteral("rs485");
}

std::optional<Link> linkFromName(const QString &name)
{
    const QString n = name.trimmed().toLower();
    for (Link l : {Link::Rs485, Link::Can}) {
        if (n == linkName(l))
            return l;
    }
    return std::nullopt;
}

QString dialectName(const DecodeContext &context)
{
    if (context.link == Link::Can)
        return context.generation == Generation::V2_3 ? QStringLiteral("CAN (old)")
                                                      : QStringLiteral("CAN V2.36");
    return QStringLiteral("RS485 ") + generationName(context.generation);
}

std::optional<Generation> generationFromWord(const QString &word)
{
    const QString w = word.trimmed().toLower();
    if (w == QLatin1String("can") || w == QLatin1String("can-old") || w == QLatin1String("canold"))
        return Generation::V2_3;
    if (w == QLatin1String("can236") || w == QLatin1String("can2.36") ||
        w == QLatin1String("2.36") || w == QLatin1String("v2.36"))
        return Generation::V2_35;
    return generationFromName(w);
}

} // namespace lk::protocol
