#include "DriveIdentity.h"

#include <protocol/Checksum.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QSet>
#include <QtCore/QStringList>

namespace lk::bus {

namespace {
QString tr(const char *text)
{
    return QCoreApplication::translate("lk::bus::DriveIdentity", text);
}
} // namespace

std::optional<DriveIdentity> DriveIdentity::parse(const QString &text, QString *error)
{
    const QString t = text.trimmed();
    const qsizetype colon = t.indexOf(QLatin1Char(':'));
    const qsizetype at = t.indexOf(QLatin1Char('@'));
    if (colon <= 0 || at < colon) {
        *error = tr("\"%1\": write ID:SERIES@GENERATION, e.g. 3:MG@2.35 or 1:MF@can236").arg(t);
        return std::nullopt;
    }
    DriveIdentity d;
    bool ok = false;
    d.id = t.left(colon).toInt(&ok);
    if (!ok || d.id < protocol::kMinId || d.id > protocol::kMaxId) {
        *error = tr("\"%1\": the ID must be 1..32").arg(t);
        return std::nullopt;
    }
    const std::optional<protocol::Series> series =
        protocol::seriesFromName(t.mid(colon + 1, at - colon - 1));
    if (!series) {
        *error = tr("\"%1\": the series must be MS, MF, MG or MH").arg(t);
        return std::nullopt;
    }
    d.series = *series;
    QString rest = t.mid(at + 1);
    const qsizetype slash = rest.indexOf(QLatin1Char('/'));
    if (slash >= 0) {
        const double gear = rest.mid(slash + 1).toDouble(&ok);
        if (!ok || !(gear >= 1)) {
            *error = tr("\"%1\": the gear ratio after / must be a number of 1 or more").arg(t);
            return std::nullopt;
        }
        d.gearRatio = gear;
        rest = rest.left(slash);
    }
    const std::optional<protocol::Generation> g = protocol::generationFromWord(rest);
    if (!g) {
        *error = tr("\"%1\": the generation must be 2.3 or 2.35 (RS485), can (old CAN) or "
                    "can236 (CAN V2.36)")
                     .arg(t);
        return std::nullopt;
    }
    d.generation = *g;
    return d;
}

std::optional<QVector<DriveIdentity>> DriveIdentity::parseList(const QString &text, QString *error)
{
    QVector<DriveIdentity> out;
    QSet<int> seen;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const std::optional<DriveIdentity> d = parse(part, error);
        if (!d)
            return std::nullopt;
        if (seen.contains(d->id)) {
            *error = tr("drive %1 is named twice").arg(d->id);
            return std::nullopt;
        }
        seen.insert(d->id);
        out.append(*d);
    }
    if (out.isEmpty()) {
        *error = tr("no drive given: write ID:SERIES@GENERATION,..., e.g. 3:MG@2.35");
        return std::nullopt;
    }
    return out;
}

} // namespace lk::bus
