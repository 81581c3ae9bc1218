#pragma once

#include <protocol/Request.h>
#include <record/BusReport.h>

#include <QtCore/QObject>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class RequestTracker;

/// Gathers a bus report over the bus: for every drive the session knows, read_model, then by
/// the generation it names read_pid and read_accel (V2.3) or every parameter with read_param
/// (V2.35: gains with Kd, limits, ramps), and read_state1; queued like any operator request
/// (never waiting). A read that fails is recorded as a problem of that drive, not as a
/// failed report.
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
    /// What a drive of `generation` is asked after its model (nullopt: unknown, state only).
    static QVector<protocol::Request> readsFor(int id,
                                               std::optional<protocol::Generation> generation);
    /// After drive `index`'s read_model: queue the reads its generation has.
    void readByGeneration(int index);
    void requestDone();

    RequestTracker *m_tracker;
    record::BusReport m_report;
    QVector<std::optional<protocol::Generation>> m_known; ///< the session's, per drive
    int m_outstanding = 0;
    int m_total = 0;
};

} // namespace lk::ui
