#pragma once

#include <QtCore/QList>
#include <QtCore/QVector>

namespace lk::bus {

/// Who an emergency stop reaches, in sending order: `first` (the known and recently
/// commanded IDs, ascending), then `others` (every other ID of 1..32, ascending). Always all
/// 32 IDs together, so that a scan that emptied the registry cannot shrink the stop.
struct StopTargets {
    QVector<int> first;
    QVector<int> others;

    QVector<int> all() const { return first + others; }
    /// `priority` (IDs outside 1..32 are ignored) and `known` make up `first`.
    static StopTargets of(const QVector<int> &priority, const QList<int> &known);
};

} // namespace lk::bus
