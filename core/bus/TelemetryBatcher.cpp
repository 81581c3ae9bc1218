#include "TelemetryBatcher.h"

#include <algorithm>

namespace lk::bus {

TelemetryBatcher::TelemetryBatcher(QObject *parent, const SingleShotTimerFactory &timers)
    : QObject(parent), m_timer(timers(
                           this, [this] { flush(); }, Qt::CoarseTimer))
{
}

void TelemetryBatcher::setRateHz(double rateHz)
{
    m_intervalMs = static_cast<int>(1000.0 / std::max(1.0, rateHz));
}

void TelemetryBatcher::add(const TelemetrySample &sample)
{
    m_pending.append(sample);
    if (!m_timer->isActive())
        m_timer->start(m_intervalMs);
}

void TelemetryBatcher::flush()
{
    m_timer->stop();
    if (m_pending.isEmpty())
        return;
    TelemetryBatch batch;
    batch.swap(m_pending);
    emit batchReady(batch);
}

} // namespace lk::bus
