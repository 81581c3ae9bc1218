#pragma once

#include "SingleShotTimer.h"
#include "TelemetrySample.h"

#include <QtCore/QObject>

#include <memory>

namespace lk::bus {

/// Gathers the samples the bus thread decodes and hands them on in batches, at most `rateHz`
/// a second: the receiving thread's event queue sees ~60 deliveries a second whatever the
/// poll rate. The first sample of a batch starts the clock, so a lone sample waits at most
/// one interval.
class TelemetryBatcher : public QObject {
    Q_OBJECT
public:
    /// `timers`: where its clock comes from (tests fire it by hand); default Qt's.
    explicit TelemetryBatcher(QObject *parent = nullptr,
                              const SingleShotTimerFactory &timers = makeQtSingleShotTimer);

    void setRateHz(double rateHz);
    /// The wait between the first sample of a batch and its hand-on.
    int intervalMs() const { return m_intervalMs; }
    void add(const TelemetrySample &sample);
    /// Hand on what is gathered now (nothing when empty) and stop the clock.
    void flush();

signals:
    void batchReady(const lk::bus::TelemetryBatch &batch);

private:
    TelemetryBatch m_pending;
    std::unique_ptr<SingleShotTimer> m_timer;
    int m_intervalMs = 16;
};

} // namespace lk::bus
