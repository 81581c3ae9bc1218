#pragma once

#include "BusConfig.h"
#include "LinkTiming.h"
#include "RequestResult.h"
#include "ScanTypes.h"
#include "SingleShotTimer.h"

#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QVector>

#include <functional>
#include <memory>

namespace lk::bus {

class BusWorker;

/// Finds drives on IDs of a range, optionally at each of the ten bauds (RS485; on CAN at the
/// link's bit rate only, without the model read CAN lacks: the generation comes from the
/// reply ID or layout, the series from the user). Runs on the bus
/// thread through the worker's queue (Operator priority; polling pauses meanwhile). After a
/// complete scan the worker knows exactly the drives found in the range (series inferred
/// from the model name). A baud sweep ends at the baud where most drives answered (the
/// original baud on a tie).
///
/// Two passes per baud, because a silent ID costs a whole timeout and most IDs are silent:
/// 1. every ID gets read_state1 (0x9A, the shortest reply every series sends) with the probe
///    timeout: wire time + 0.5 ms turnaround + BusConfig::minMarginMs, no retry. An ID that
///    answers is then asked read_model (0x12) with the adaptive timeout.
/// 2. silent IDs are probed again with the adaptive timeout (which has learned from any late
///    reply) when pass 1 heard a reply after its timeout, i.e. the link is slower than the
///    probe timeout assumed (a USB adapter's 1-16 ms latency), or when ScanOptions::retries
///    asks for it. Before deciding, a scan with silent IDs listens for stragglers for
///    max(adaptive margin, BusConfig::initialMarginMs). A third pass follows only if pass 2
///    itself heard late replies.
class Scanner : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxReprobes = 2; ///< immediate re-probes after a corrupt reply
    static constexpr int kMaxPasses = 3;

    /// `timers`: the worker's (its grace timer runs on the worker's time, like its probes).
    Scanner(BusWorker &worker, const SingleShotTimerFactory &timers, QObject *parent = nullptr);

    /// Start a scan; a running one is cancelled first.
    void start(const ScanOptions &options);
    /// Stop after the probe on the wire; finished() follows with cancelled = true.
    void cancel();
    /// Stop because the bus went away; finished() follows with `error`.
    void abort(const QString &error);
    bool isRunning() const { return m_running; }
    /// A baud sweep is replacing the transport: its close is not a disconnect.
    bool isReopening() const { return m_reopening; }

    /// How long pass 1 of a scan of `idCount` IDs at `baud` takes when `answering` of them
    /// answer, with the margins of `config` as a new session has them: each silent ID waits
    /// out the probe's timeout (BusConfig::minMarginMs, on a timer of whole milliseconds;
    /// a probe's quiet period ends with it while the link is as fast as that margin), each
    /// drive costs its probe and its read_model on the wire, and a pass with a silent ID then
    /// listens for stragglers (BusConfig::initialMarginMs, as a fresh link has it). A slow
    /// link's second pass and the host's own delays are left out.
    static double estimatedSeconds(int idCount, int baud, const BusConfig &config,
                                   int answering = 0);
    /// The same on any link (CAN: no model read, CAN frames and reply time).
    static double estimatedSeconds(int idCount, const LinkTiming &timing, const BusConfig &config,
                                   int answering = 0);
    /// estimatedSeconds() over every baud `options` scans (the link's `baud` unless it
    /// sweeps); `answeringAt` gives how many IDs of the range are expected to answer at a
    /// baud (none when absent).
    static double estimatedSeconds(const ScanOptions &options, int baud, const BusConfig &config,
                                   const QMap<int, int> &answeringAt = {});
    /// The bauds `options` scans, in order, when the link is at `baud`.
    static QVector<int> baudsToScan(const ScanOptions &options, int baud);
    /// How many drives `motors` holds: a drive that answered at several bauds (a simulated
    /// bus answers at every one) is one drive. Hits of one ID are one drive unless both
    /// read their model and the models differ.
    static int driveCount(const QVector<FoundMotor> &motors);

signals:
    void progress(const lk::bus::ScanProgress &progress);
    void found(const lk::bus::FoundMotor &motor);
    void finished(const lk::bus::ScanSummary &summary);

private:
    void beginBaud();
    void reopenAndBegin();
    void beginPass(int pass, QVector<int> ids);
    void probe();
    void onProbe(const RequestResult &r);
    void onModel(const RequestResult &r, FoundMotor motor);
    void addFound(FoundMotor motor);
    /// A drive answered the probe on CAN: found without a model read.
    void foundOnCan(FoundMotor motor);
    void next();
    void endPass();
    void afterGrace();
    void nextBaud();
    void endOfBauds();
    void stop(bool cancelled, const QString &error);
    void finish();
    void submitScanRequest(protocol::Command command, int retries, double firstTimeoutS,
                           std::function<void(const RequestResult &)> done);
    int currentBaud() const { return m_bauds.value(m_baudIndex); }
    int currentId() const { return m_ids.value(m_index); }

    BusWorker &m_worker;
    ScanOptions m_options;
    QVector<int> m_bauds;
    int m_baudIndex = 0;
    int m_pass = 1;
    QVector<int> m_ids;     ///< IDs of the current pass
    int m_index = 0;        ///< into m_ids
    QVector<int> m_silent;  ///< IDs of the current pass that did not answer
    double m_passStart = 0; ///< session time the pass began: its late replies count
    int m_done = 0;
    int m_reprobes = 0; ///< re-probes of the current ID after corrupt replies
    int m_total = 0;
    int m_originalBaud = 0;
    QVector<FoundMotor> m_found;
    double m_startS = 0;                      ///< session time the scan started
    std::unique_ptr<SingleShotTimer> m_grace; ///< listening for late replies after pass 1
    quint64 m_generation = 0;                 ///< callbacks of an older scan are ignored
    bool m_running = false;
    bool m_waiting = false; ///< one of our requests is queued or on the wire
    bool m_reopening = false;
    bool m_cancelled = false;
    QString m_error;
};

} // namespace lk::bus
