#pragma once

#include "FrequencyResponse.h"
#include "FrequencySweepPlan.h"
#include "GainKeeper.h"
#include "StepTestRunner.h"
#include "TuningEnd.h"

#include <bus/PollPlan.h>
#include <bus/RequestResult.h>
#include <bus/SetpointStop.h>
#include <bus/TelemetrySample.h>

#include <QtCore/QObject>
#include <QtCore/QTimer>

#include <optional>

namespace lk::bus {
class BusSession;
struct ConnectionStatus;
} // namespace lk::bus

namespace lk::tuning {

/// What a frequency sweep measured and how it ended.
struct FrequencySweepResult {
    FrequencySweepSpec spec;
    FrequencyResponse response;
    std::optional<LoopGains> gains;   ///< as read before anything moved
    std::optional<double> startSpeed; ///< dps, read before anything moved (speed loop)
    std::optional<double> startAngle; ///< deg, multi-turn, read before (position loop)
    /// The setpoints as the drive acknowledged them (dps or deg, at the times they were
    /// written: the reply's time less its latency) and the speed each reply carried: the raw
    /// data behind the points.
    QVector<double> time, setpoint, speed;
    qint64 sent = 0;
    StepTestFailure failure = StepTestFailure::None;
    safety::Verdict refusal; ///< Refused: the limit
    double refusedDps = 0;
    QString message;       ///< English: why it failed, and what the drive was left doing
    TuningOutcome outcome; ///< the same as facts (the views word them from these)
    bool ok() const { return failure == StepTestFailure::None; }
};

/// Measures the speed or position loop's frequency response on a BusSession: reads the drive's
/// gains and acceleration limit (nothing runs without them; the limit is lifted in RAM for the
/// sweep and put back after it, whatever happens), its speed (or its multi-turn angle, which a
/// position sweep is centred on), plans the stepped sine (FrequencySweepPlan: a
/// refusal sends nothing), pauses the poll plan (each setpoint's reply is a sample), runs the
/// sine from the setpoint stream on the bus thread, fits each frequency on the replies' real
/// times and gives the poll plan back. At the end it sets the speed read at the start again
/// (or the spec's returnSpeedDps, the speed the caller commanded); a
/// position sweep ends on the angle it started from. The replies carry the speed, not the
/// angle: a position point is the speed's response over jw (the angle of a sine).
///
/// abort() (Esc, Ctrl-C) halts the stream, sends motor off to the drive (an emergency stop:
/// every ID) and writes the gains read back to RAM; failed(Aborted) follows once both ended.
/// Nothing else may send motion commands to the drive while it runs.
class FrequencySweepRunner : public QObject {
    Q_OBJECT
public:
    explicit FrequencySweepRunner(bus::BusSession &session, QObject *parent = nullptr);
    ~FrequencySweepRunner() override; ///< running: the stream stops and the motor goes off

    /// false (nothing happens) while one runs. Every outcome arrives as finished() or
    /// failed(), never from inside start().
    bool start(const FrequencySweepSpec &spec, const safety::SoftLimits &limits);
    void abort();
    bool isRunning() const { return m_phase != Phase::Idle; }
    const FrequencySweepPlan &plan() const { return m_plan; }
    /// Grace after the stepped sine's end before the stream is stopped: the last replies.
    static constexpr int kTailMs = 150;

signals:
    void started(const lk::tuning::FrequencySweepPlan &plan);
    void finished(const lk::tuning::FrequencySweepResult &result);
    void failed(const lk::tuning::FrequencySweepResult &result);

private:
    enum class Phase { Idle, ReadingGains, ReadingSpeed, Sweeping, Returning, Aborting };

    void onGainsRead();
    void readSpeed();
    void onSpeedRead(const bus::RequestResult &result);
    void onAngleRead(const bus::RequestResult &result);
    /// The read before the sweep went unanswered: nothing was sent.
    void unanswered(const bus::RequestResult &result, const char *read);
    void startSweep();
    void onCompleted(const bus::RequestResult &result);
    void onTelemetry(const bus::TelemetryBatch &batch);
    void onStreamStopped(const bus::SetpointStop &stop);
    void onConnection(const bus::ConnectionStatus &status);
    void sweepDone();
    void returnToStart();
    /// Where a speed sweep ends: the spec's returnSpeedDps, else the speed read before it.
    double returnSpeed() const;
    void analyse();
    void restorePolling();
    void end(StepTestFailure failure, SearchEnd why, DriveLeft drive, bool restored,
             const QString &message);
    /// Ends before anything moved: the acceleration limit, if it was lifted, goes back first.
    void endBeforeMotion(StepTestFailure failure, SearchEnd why, const QString &message);
    void haltAndRestore(StepTestFailure failure, SearchEnd why, const QString &message);

    bus::BusSession &m_session;
    GainKeeper m_keeper;
    Phase m_phase = Phase::Idle;
    FrequencySweepSpec m_spec;
    safety::SoftLimits m_limits;
    FrequencySweepPlan m_plan;
    FrequencySweepResult m_result;
    quint64 m_run = 0;
    quint64 m_stream = 0;
    QVector<double> m_sentValues; ///< acknowledged setpoints, in order
    QVector<double> m_latencies;  ///< their write-to-reply times, seconds
    QVector<double> m_replyTimes; ///< their replies' samples, in order
    QVector<double> m_replySpeeds;
    std::optional<bus::PollPlan> m_previousPlan;
    bool m_pollingPaused = false;
    QTimer m_endTimer;
};

} // namespace lk::tuning

Q_DECLARE_METATYPE(lk::tuning::FrequencySweepResult)
