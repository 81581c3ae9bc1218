#pragma once

#include <record/BusReport.h>

#include <QtCore/QObject>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class RequestTracker;

/// Gathers a bus report over the bus: for every drive the session knows, read_model,
/// read_pid, read_accel and read_state1, queued like any operator request (never waiting).
/// A read that fails is recorded as a problem of that drive, not as a failed report.
class BusReportGatherer : public QObject {
    Q_OBJECT
public:
    explicit BusReportGatherer(QObject *parent = nullptr);

    /// Starts gathering from `session` (an earlier run is abandoned). With no known drive the
    /// report is finished at once, empty.
    void start(lk::bus::BusSession *session, const QString &toolVersion = {});
    void cancel();
    bool isRunning() const { return m_outstanding > 0; }

signals:
    void progress(int done, int total);
    void finished(const lk::record::BusReport &report);

private:
    void requestDone();

    RequestTracker *m_tracker;
    record::BusReport m_report;
    int m_outstanding = 0;
    int m_total = 0;
};

} // namespace lk::ui
