#pragma once

#include "BusClock.h"
#include "SingleShotTimer.h"
#include "StatisticsCollector.h"
#include "TrafficEvent.h"
#include "TrafficRecorder.h"

#include <QtCore/QObject>

#include <memory>

namespace lk::bus {

class MotorRegistry;

/// What the bus engine shows of itself besides results, on the bus thread: its counters
/// (StatisticsCollector; statisticsDue every 1/statisticsHz, so that the owner emits a
/// snapshot) and, while enabled, the raw traffic (TrafficRecorder, delivered every 50 ms),
/// each frame taken apart as its ID decodes at that moment: a series learnt later does not
/// change how an earlier row reads.
class BusDiagnostics : public QObject {
    Q_OBJECT
public:
    BusDiagnostics(const MotorRegistry &motors, std::shared_ptr<BusClock> clock,
                   const SingleShotTimerFactory &timers, QObject *parent = nullptr);
    ~BusDiagnostics() override;

    StatisticsCollector &counters() { return m_stats; }
    const StatisticsCollector &counters() const { return m_stats; }

    /// Starts the statistics timer; a running one starts over at the new rate (as
    /// QTimer::setInterval: from now).
    void startStatistics(double statisticsHz);
    void setStatisticsHz(double statisticsHz);
    void setTrafficCapture(bool enabled);
    /// Stops both timers (the bus is shut down).
    void stop();

    void recordSent(const QByteArray &bytes, int id);
    void recordTimeout(int id, quint8 command);
    void recordNote(const QString &text);
    void recordParseEvent(const protocol::ParseEvent &event);

signals:
    void statisticsDue();
    void trafficCaptured(const lk::bus::TrafficBatch &batch);

private:
    double now() const { return static_cast<double>(m_clock->nowNs()) * 1e-9; }
    void flushTraffic();

    const MotorRegistry &m_motors;
    std::shared_ptr<BusClock> m_clock;
    StatisticsCollector m_stats;
    TrafficRecorder m_traffic;
    int m_statsIntervalMs = 1000;
    std::unique_ptr<SingleShotTimer> m_statsTimer;   ///< periodic: restarted on its timeout
    std::unique_ptr<SingleShotTimer> m_trafficTimer; ///< periodic while capturing
};

} // namespace lk::bus
