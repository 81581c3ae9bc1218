#pragma once

#include "TrafficCounts.h"
#include "TrafficEvent.h"

#include <QtCore/QList>

#include <functional>
#include <optional>

namespace lk::bus {

/// Traffic batches waiting for a log that keeps at most `limit` rows: kept as they came
/// (shared, not copied row by row), and a batch none of whose rows could be among the newest
/// `limit` is dropped and only counted. Whole batches are kept: the newest `limit` rows (when
/// there are that many) and fewer than a batch more. A hidden Traffic view and a replay's Load all,
/// which hands on millions of rows, keep their backlog in one.
class TrafficBacklog {
public:
    explicit TrafficBacklog(qsizetype limit = 0) : m_limit(limit) {}

    /// The newest this many rows kept, in whole batches (0: no limit); from the next append.
    void setLimit(qsizetype limit) { m_limit = limit; }
    qsizetype limit() const { return m_limit; }
    /// Where a dropped batch goes to be freed (none: freed here, in append). Its rows were
    /// built long before they are dropped, out of every cache by then: freeing them is a
    /// miss per byte array, which a caller on a busy thread may rather have done elsewhere.
    void setDisposal(std::function<void(TrafficBatch &&)> dispose)
    {
        m_dispose = std::move(dispose);
    }

    /// Keep `batch`, dropping older batches past the limit. `counts`, when given, are the
    /// batch's own (TrafficCounts::add of each row, taken while the rows were built): a dropped
    /// batch is then counted without reading its rows again.
    void append(const TrafficBatch &batch, std::optional<TrafficCounts> counts = std::nullopt);
    /// Rows dropped elsewhere before they reached this backlog, counted with its own.
    void addDropped(const TrafficCounts &counts) { m_dropped += counts; }

    bool isEmpty() const { return m_batches.isEmpty() && m_dropped.events == 0; }
    qsizetype rows() const { return m_rows; }
    const QList<TrafficBatch> &batches() const { return m_batches; }
    const TrafficCounts &dropped() const { return m_dropped; }

    /// The rows kept, oldest first, as one batch (the backlog keeps none after).
    TrafficBatch takeRows();
    /// The counts of the rows dropped so far (the backlog counts from zero after).
    TrafficCounts takeDropped();
    void clear();

private:
    qsizetype m_limit = 0;
    QList<TrafficBatch> m_batches; ///< oldest first
    /// Per batch of m_batches, its counts when append() was given them.
    QList<std::optional<TrafficCounts>> m_counts;
    qsizetype m_rows = 0; ///< the rows of m_batches
    TrafficCounts m_dropped;
    std::function<void(TrafficBatch &&)> m_dispose;
};

} // namespace lk::bus
