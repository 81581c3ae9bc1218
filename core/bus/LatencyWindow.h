#pragma once

#include "BusStatistics.h"

#include <QtCore/QVector>

namespace lk::bus {

/// The last N latency samples (seconds) with order statistics; bounded memory.
class LatencyWindow {
public:
    static constexpr int kDefaultCapacity = 256;
    LatencyWindow() : LatencyWindow(kDefaultCapacity) {}
    explicit LatencyWindow(int capacity);

    void add(double seconds);
    void clear();
    int size() const { return m_samples.size(); }
    bool isEmpty() const { return m_samples.isEmpty(); }
    /// Quantile q in 0..1 (nearest rank); 0 when empty.
    double quantile(double q) const;
    double min() const { return quantile(0); }
    double median() const { return quantile(0.5); }
    double p95() const { return quantile(0.95); }
    double max() const { return quantile(1); }
    LatencySummary summaryMs() const;

private:
    int m_capacity;
    QVector<double> m_samples; ///< ring buffer once full
    int m_next = 0;
    QVector<double> m_sorted; ///< the same samples, ascending
};

} // namespace lk::bus
