#pragma once

#include <QtCore/QList>
#include <QtCore/QVector>

namespace lk::bus {

/// Who an emergency stop reaches, in sending order: `first` (the urgent IDs, ascending, then
/// the other known ones, ascending), then `others` (every other ID of 1..32, ascending).
/// Always all 32 IDs together, so that a scan that emptied the registry cannot shrink the
/// stop.
struct StopTargets {
    QVector<int> first;
    QVector<int> others;

    QVector<int> all() const { return first + others; }
    /// `urgent` (commanded or seen moving) and then `known` (known or answering) make up
    /// `first`; IDs outside 1..32 are ignored, each ID comes once.
    static StopTargets of(const QVector<int> &urgent, const QList<int> &known);
};

} // namespace lk::bus
