#pragma once

#include "TelemetrySample.h"

#include <QtCore/QObject>
#include <QtCore/QTimer>

namespace lk::bus {

/// Gathers the samples the bus thread decodes and hands them on in batches, at most `rateHz`
/// a second: the receiving thread's event queue sees ~60 deliveries a second whatever the
/// poll rate. The first sample of a batch starts the clock, so a lone sample waits at most
/// one interval.
class TelemetryBatcher : public QObject {
    Q_OBJECT
public:
    explicit TelemetryBatcher(QObject *parent = nullptr);

    void setRateHz(double rateHz);
    void add(const TelemetrySample &sample);
    /// Hand on what is gathered now (nothing when empty) and stop the clock.
    void flush();

signals:
    void batchReady(const lk::bus::TelemetryBatch &batch);

private:
    TelemetryBatch m_pending;
    QTimer m_timer{this}; // a child: it moves to the bus thread with its owner
    int m_intervalMs = 16;
};

} // namespace lk::bus
