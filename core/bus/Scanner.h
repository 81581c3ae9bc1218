#pragma once

#include "RequestResult.h"
#include "ScanTypes.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>
#include <QtCore/QVector>

namespace lk::bus {

class BusWorker;

/// Finds drives: read_model (0x12) to each ID of a range, then read_state1 (0x9A) from each
/// one that answers, optionally at each of the nine bauds. Runs on the bus thread through the
/// worker's queue (Operator priority; polling pauses meanwhile). After a complete scan the
/// worker knows exactly the drives found in the range (series inferred from the model name).
/// A baud sweep ends at the baud where most drives answered (the original baud on a tie).
class Scanner : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxReprobes = 2;

    Scanner(BusWorker &worker, QObject *parent = nullptr);

    /// Start a scan; a running one is cancelled first.
    void start(const ScanOptions &options);
    /// Stop after the probe on the wire; finished() follows with cancelled = true.
    void cancel();
    /// Stop because the bus went away; finished() follows with `error`.
    void abort(const QString &error);
    bool isRunning() const { return m_running; }
    /// A baud sweep is replacing the transport: its close is not a disconnect.
    bool isReopening() const { return m_reopening; }

    /// Series from the motor name, else from the driver name; nullopt when neither tells.
    static std::optional<protocol::Series> inferSeries(const protocol::ModelInfo &model);

signals:
    void progress(const lk::bus::ScanProgress &progress);
    void found(const lk::bus::FoundMotor &motor);
    void finished(const lk::bus::ScanSummary &summary);

private:
    void beginBaud();
    void probe();
    void onModel(const RequestResult &r);
    void onState(const RequestResult &r, FoundMotor motor);
    void advance();
    void endOfBauds();
    void stop(bool cancelled, const QString &error);
    void finish();
    void submitScanRequest(protocol::Command command, int retries,
                           std::function<void(const RequestResult &)> done);
    int currentBaud() const { return m_bauds.value(m_baudIndex); }

    BusWorker &m_worker;
    ScanOptions m_options;
    QVector<int> m_bauds;
    int m_baudIndex = 0;
    int m_id = 0;
    int m_done = 0;
    int m_reprobes = 0; ///< re-probes of the current ID after corrupt replies
    int m_total = 0;
    int m_originalBaud = 0;
    QVector<FoundMotor> m_found;
    QElapsedTimer m_elapsed;
    quint64 m_generation = 0; ///< callbacks of an older scan are ignored
    bool m_running = false;
    bool m_waiting = false; ///< one of our requests is queued or on the wire
    bool m_reopening = false;
    bool m_cancelled = false;
    QString m_error;
};

} // namespace lk::bus
