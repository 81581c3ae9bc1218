#pragma once

#include "DriveSnapshot.h"

#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::fleet {

/// One parameter of two drives side by side.
struct DiffRow {
    enum class State { Same, Differs, Unknown };
    QString key;
    std::optional<qint64> a; ///< nullopt: not known (not read, or the generation lacks it)
    std::optional<qint64> b;
    State state() const
    {
        if (!a || !b)
            return State::Unknown;
        return *a == *b ? State::Same : State::Differs;
    }
};

/// Compares drives' parameters key by key; a value not known is never taken as equal or as 0.
class ParamDiff {
public:
    /// Every key of either drive, in the catalogue's order (a's generation first).
    static QVector<DiffRow> rows(const DriveSnapshot &a, const DriveSnapshot &b);
    /// The keys of all `drives`, in the catalogue's order (V2.3's keys, then V2.35's new ones).
    static QStringList keys(const QVector<DriveSnapshot> &drives);
    /// The value of `key` in `drive`, if known.
    static std::optional<qint64> value(const DriveSnapshot &drive, const QString &key);
    static const char *stateName(DiffRow::State state); ///< "same", "differs", "unknown"
};

} // namespace lk::fleet
