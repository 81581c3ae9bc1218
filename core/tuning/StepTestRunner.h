#pragma once

#include "StepTestPlan.h"
#include "StepTrace.h"

#include <bus/PollPlan.h>
#include <bus/RequestResult.h>
#include <bus/TelemetrySample.h>
#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QTimer>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {
class BusSession;
struct ConnectionStatus;
} // namespace lk::bus

namespace lk::tuning {

/// One setpoint as it went on the bus.
struct StepSent {
    StepSetpoint setpoint;
    /// Host time of the drive's reply to it (the reply's telemetry sample, the trace's clock);
    /// NaN when none was seen.
    double time = StepTrace::missing();
    bool acknowledged = false; ///< the drive answered it (it may have acted without answering)
};

/// Why a step test did not finish.
enum class StepTestFailure {
    None,
    BadSpec,      ///< the spec itself (durations, periods, FROM = TO, wire range); nothing sent
    Refused,      ///< a setpoint breaks a limit (verdict names it); nothing sent
    Silent,       ///< the drive did not answer a read or a setpoint
    Disconnected, ///< the bus went away
    Aborted,      ///< abort() was called
};

/// What a step test did: the trace, what was sent, and how it ended.
struct StepTestResult {
    StepTestSpec spec;
    StepTrace trace; ///< samples from the pre-roll's reply on; edges at their replies' times
    QVector<StepSent> sent;
    double sampleRateHz = 0;          ///< samples per second over the trace
    std::optional<double> startValue; ///< the speed (dps) or angle (deg) read before the test
    safety::SpeedBound bound = safety::SpeedBound::None; ///< as StepTestPlan::bound()
    double boundDps = 0;
    StepTestFailure failure = StepTestFailure::None;
    StepRefusal refusal; ///< a Refused test: the setpoint and the limit (VerdictText words it)
    QString message;     ///< English: why it failed, and what may still be moving
    bool ok() const { return failure == StepTestFailure::None; }
    bool anythingSent() const { return !sent.isEmpty(); }
};

/// Runs one step test on a BusSession: reads where the drive is (0x92 for a position test,
/// 0x9C for a speed test), plans it (StepTestPlan: a refusal sends nothing), focuses the
/// session's poll plan on the drive (speed: 0x9C; position: 0x92 and 0x9C, the same round's
/// iq as the angle's effort), sends the setpoints at their times (Operator priority, the
/// session's retries for absolute commands), records the drive's samples into a StepTrace,
/// gives the previous poll plan back and emits finished() or failed().
///
/// Lives in the caller's thread, like the session. It never sends motor off: abort() only stops
/// sending (the emergency stop is the caller's, EmergencyStopControl / lkctl stop). The drive
/// keeps its last command after a test, aborted or not: a speed test leaves it turning at
/// FROM (or, aborted, at the last setpoint sent), a position test at or moving to its last
/// target. Nothing else may send motion commands to the drive while a test runs: its replies
/// would be taken for the test's.
class StepTestRunner : public QObject {
    Q_OBJECT
public:
    explicit StepTestRunner(bus::BusSession &session, QObject *parent = nullptr);
    ~StepTestRunner() override; ///< a running test is aborted (its poll plan given back)

    /// Start a test; false (nothing happens) while one is running. The drive's series is the
    /// session's (series(id)); `gearRatio` is the motor's (ModelNameInfo) for the one-output-
    /// turn rule. Every outcome arrives as finished() or failed(), never from inside start().
    bool start(const StepTestSpec &spec, const safety::SoftLimits &limits, double gearRatio = 1);
    /// Stop sending at once and end the test with failed(Aborted). A setpoint already handed
    /// to the session may still go out (the emergency stop cancels queued motion). Sends
    /// nothing itself.
    void abort();
    bool isRunning() const { return m_phase != Phase::Idle; }
    /// The plan of the running (or last) test; empty before the drive was read.
    const StepTestPlan &plan() const { return m_plan; }

    /// How long the runner waits, after the last setpoint's reply, for that reply's sample
    /// (telemetry arrives in batches, up to 1/telemetryHz late).
    static constexpr int kSampleGraceMs = 250;

signals:
    /// The drive was read and the test planned: the setpoints are about to go out.
    void started(const lk::tuning::StepTestPlan &plan);
    void finished(const lk::tuning::StepTestResult &result);
    /// Refused, bad spec, silent drive, disconnected or aborted; `result` says what was sent.
    void failed(const lk::tuning::StepTestResult &result);

private:
    enum class Phase { Idle, Reading, Running, Draining };

    /// Setpoint `index` of run `run` ended (a callback of BusSession::send).
    void onSetpointDone(quint64 run, int index, const bus::RequestResult &result);
    void onTelemetry(const QVector<bus::TelemetrySample> &batch);
    void onConnection(const bus::ConnectionStatus &status);
    void onRead(const bus::RequestResult &result);
    void begin(std::optional<double> angleDeg);
    void focusPolling();
    void restorePolling();
    void sendDue();
    void drainCheck();
    void finishRun();
    void buildTrace();
    void end(StepTestFailure failure, const QString &message);
    QString stillMoving() const;

    bus::BusSession &m_session;
    Phase m_phase = Phase::Idle;
    StepTestSpec m_spec;
    safety::SoftLimits m_limits;
    double m_gearRatio = 1;
    StepTestPlan m_plan;
    StepTestResult m_result;
    /// Counts start(): a completion of an earlier run (aborted, then started again) finds a
    /// different number and is ignored.
    quint64 m_run = 0;
    int m_next = 0;                          ///< the next setpoint to send
    int m_replySamples = 0;                  ///< motion replies seen in the telemetry
    int m_completions = 0;                   ///< setpoints whose completion arrived
    QVector<bus::TelemetrySample> m_samples; ///< the drive's samples since the pre-roll went out
    std::optional<bus::PollPlan> m_previousPlan;
    bool m_focused = false; ///< the session polls the focus plan: give m_previousPlan back
    QElapsedTimer m_clock;
    QTimer m_sendTimer;
    QTimer m_graceTimer;
};

} // namespace lk::tuning

Q_DECLARE_METATYPE(lk::tuning::StepTestResult)
Q_DECLARE_METATYPE(lk::tuning::StepTestPlan)
