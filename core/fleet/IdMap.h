#pragma once

#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::fleet {

/// The drive lists and ID maps of backup, restore and clone, as lkctl and the Parameters view
/// take them.
class IdMap {
public:
    /// "all" -> empty (every drive that answers), "3", "1,2,5", "1-4"; nullopt with `error`
    /// naming the part otherwise.
    static std::optional<QVector<int>> parseIds(const QString &text, QString *error);
    /// "3:5,4:6" (old drive 3 -> new drive 5); nullopt with `error` naming the entry, also
    /// when a drive is mapped twice or two drives onto one.
    static std::optional<QMap<int, int>> parseMap(const QString &text, QString *error);
};

} // namespace lk::fleet
