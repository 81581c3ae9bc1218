#pragma once

#include <protocol/Series.h>
#include <safety/SoftLimits.h>
#include <tuning/StepRun.h>
#include <tuning/StepTestRunner.h>

#include <QtCore/QJsonObject>
#include <QtCore/QPointer>
#include <QtWidgets/QGroupBox>

#include <functional>
#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class StepRunList;

/// What the step-test panel needs to know about the selected drive, refreshed by its view.
struct StepTestDrive {
    QPointer<bus::BusSession> session;
    int id = 0;
    bool canSend = false; ///< a session, a connected link and this drive
    std::optional<protocol::Series> series;
    QString model;      ///< motor name, empty if unknown
    QString generation; ///< "v2.3" / "v2.35", empty if unknown
    double gearRatio = 1;
};

/// Where the panel gets what a run records and what bounds it: the soft limits in force (the
/// Control view's; nullopt with the reason when they cannot be used), the gains and ramps the
/// drive holds (only values that were read), and the drive's current (power) limit.
struct StepTestSources {
    std::function<std::optional<safety::SoftLimits>(QString *why)> limits;
    std::function<QJsonObject()> gains;
    std::function<QJsonObject()> ramps;
    std::function<std::optional<double>()> effortLimit;
    /// The drive's multi-turn angle last polled (rotor deg): a position test's default FROM.
    std::function<std::optional<double>()> angleDeg;
};

/// Runs a step test on the selected drive (tuning::StepTestRunner: every setpoint checked
/// against the soft limits before anything moves) and keeps each finished run in a
/// StepRunList with the gains in force. "Repeat" reruns the last test with the gains the drive
/// holds now: the write-test-compare loop. While a test runs, its button is the emergency stop.
class StepTestPanel : public QGroupBox {
    Q_OBJECT
public:
    StepTestPanel(StepRunList *runs, QWidget *parent = nullptr);
    ~StepTestPanel() override;

    void setSources(const StepTestSources &sources) { m_sources = sources; }
    const StepTestSources &sources() const { return m_sources; }
    void setDrive(const StepTestDrive &drive);

    /// The test the fields describe (for the selected drive).
    tuning::StepTestSpec spec() const;
    void setSpec(const tuning::StepTestSpec &spec);
    /// Starts the test of the fields. Returns false (and says why) when nothing was started.
    bool runTest();
    /// Runs the last test again (same loop, FROM, TO, duration, periods, drive).
    bool repeatLast();
    bool canRepeat() const;
    bool isRunning() const;
    /// Stops sending setpoints at once (the emergency stop calls it before its Motor Off).
    void halt(const QString &reason);
    QString statusText() const;

signals:
    /// A run finished and was added to the list under StepRunList key `key`.
    void runFinished(int key);
    /// The user asked to stop a running test: the emergency stop's job (Motor Off to all).
    void emergencyStopRequested();
    void runningChanged(bool running);

private:
    QWidget *buildFields();
    void loopChanged();
    bool start(const tuning::StepTestSpec &spec);
    void onFinished(const tuning::StepTestResult &result);
    void onFailed(const tuning::StepTestResult &result);
    QString failureText(const tuning::StepTestResult &result) const;
    QString stillMoving(const tuning::StepTestResult &result) const;
    void setStatus(const QString &text, bool error = false);
    void refreshEnabled();
    void ensureRunner();

    StepRunList *m_runs;
    StepTestSources m_sources;
    StepTestDrive m_drive;
    std::unique_ptr<tuning::StepTestRunner> m_runner;
    QPointer<bus::BusSession> m_runnerSession;
    std::optional<tuning::StepTestSpec> m_last;
    // What the running test records besides its trace, fixed when it starts.
    tuning::StepRun m_pending;
    QComboBox *m_loop = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QDoubleSpinBox *m_duration = nullptr;
    QSpinBox *m_periods = nullptr;
    QPushButton *m_run = nullptr;
    QPushButton *m_repeat = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace lk::ui
