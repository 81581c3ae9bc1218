#include "IdMap.h"

#include <protocol/Checksum.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>

namespace lk::fleet {

namespace {
std::optional<int> idOf(const QString &text)
{
    bool ok = false;
    const int id = text.trimmed().toInt(&ok);
    if (!ok || id < protocol::kMinId || id > protocol::kMaxId)
        return std::nullopt;
    return id;
}
} // namespace

std::optional<QVector<int>> IdMap::parseIds(const QString &text, QString *error)
{
    QVector<int> ids;
    if (text == QLatin1String("all"))
        return ids;
    for (const QString &part : text.split(QLatin1Char(','))) {
        const QStringList range = part.split(QLatin1Char('-'));
        const std::optional<int> from = idOf(range.first());
        const std::optional<int> to = range.size() == 2 ? idOf(range.last()) : from;
        if (range.size() > 2 || !from || !to || *to < *from) {
            *error = QCoreApplication::translate("lk::fleet::IdMap",
                                                 "'%1' is not a drive ID 1..32 or a range "
                                                 "such as 1-4 (all, 3, 1,2,5 or 1-4)")
                         .arg(part);
            return std::nullopt;
        }
        for (int id = *from; id <= *to; ++id) {
            if (!ids.contains(id))
                ids << id;
        }
    }
    return ids;
}

std::optional<QMap<int, int>> IdMap::parseMap(const QString &text, QString *error)
{
    QMap<int, int> map;
    QList<int> targets;
    for (const QString &part : text.split(QLatin1Char(','))) {
        const QStringList ab = part.split(QLatin1Char(':'));
        const std::optional<int> a = ab.size() == 2 ? idOf(ab.first()) : std::nullopt;
        const std::optional<int> b = ab.size() == 2 ? idOf(ab.last()) : std::nullopt;
        if (!a || !b) {
            *error = QCoreApplication::translate(
                         "lk::fleet::IdMap",
                         "'%1' is not OLD:NEW with two drive IDs 1..32 (e.g. 3:5,4:6)")
                         .arg(part);
            return std::nullopt;
        }
        if (map.contains(*a) || targets.contains(*b)) {
            *error = QCoreApplication::translate("lk::fleet::IdMap",
                                                 "'%1' maps a drive that is already mapped")
                         .arg(part);
            return std::nullopt;
        }
        map.insert(*a, *b);
        targets << *b;
    }
    return map;
}

} // namespace lk::fleet
