#include "StepTestPanel.h"

#include "MetricText.h"
#include "StepRunList.h"

#include <panels/Format.h>
#include <panels/StatusColors.h>

#include <bus/BusSession.h>
#include <text/VerdictText.h>

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

#include <cmath>

namespace lk::ui {

using tuning::StepLoop;
using tuning::StepTestFailure;
using tuning::StepTestResult;
using tuning::StepTestSpec;

namespace {
constexpr double kDefaultSpeedStepDps = 360;
constexpr double kDefaultPositionStepDeg = 90;
constexpr double kSpinLimit = 1e7; // the soft limits bound the values, not the spin boxes
} // namespace

StepTestPanel::StepTestPanel(StepRunList *runs, QWidget *parent)
    : QGroupBox(tr("Step test"), parent), m_runs(runs)
{
    setObjectName(QStringLiteral("stepTestPanel"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildFields());
    auto *buttons = new QHBoxLayout;
    m_run = new QPushButton(tr("Test step"), this);
    m_run->setObjectName(QStringLiteral("testStep"));
    m_repeat = new QPushButton(tr("Repeat last test"), this);
    m_repeat->setObjectName(QStringLiteral("repeatStep"));
    m_repeat->setToolTip(tr("Run the last test again with the gains the drive holds now."));
    buttons->addWidget(m_run);
    buttons->addWidget(m_repeat);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("stepStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (isRunning())
            emit emergencyStopRequested();
        else
            runTest();
    });
    connect(m_repeat, &QPushButton::clicked, this, &StepTestPanel::repeatLast);
    setStatus(tr("Steps the speed or position loop of the selected drive and measures the "
                 "response. Every setpoint is checked against the soft limits (Control view) "
                 "before anything moves; Esc stops the motors."));
    refreshEnabled();
}

StepTestPanel::~StepTestPanel() = default;

QWidget *StepTestPanel::buildFields()
{
    auto *w = new QWidget(this);
    auto *form = new QFormLayout(w);
    form->setContentsMargins(0, 0, 0, 0);
    m_loop = new QComboBox(w);
    m_loop->setObjectName(QStringLiteral("stepLoop"));
    m_loop->addItem(tr("Speed loop"), int(StepLoop::Speed));
    m_loop->addItem(tr("Position loop"), int(StepLoop::Position));
    auto spin = [w](const QString &name, double min, double max, int decimals) {
        auto *s = new QDoubleSpinBox(w);
        s->setObjectName(name);
        s->setRange(min, max);
        s->setDecimals(decimals);
        s->setKeyboardTracking(false);
        // The range's widest text would make the boxes (and the view) too wide for 1366 px.
        s->setMinimumWidth(70);
        return s;
    };
    m_from = spin(QStringLiteral("stepFrom"), -kSpinLimit, kSpinLimit, 2);
    m_to = spin(QStringLiteral("stepTo"), -kSpinLimit, kSpinLimit, 2);
    m_to->setValue(kDefaultSpeedStepDps);
    m_duration = spin(QStringLiteral("stepDuration"), StepTestSpec::kMinDurationS,
                      StepTestSpec::kMaxDurationS, 2);
    m_duration->setValue(1.0);
    m_duration->setSuffix(tr(" s"));
    m_periods = new QSpinBox(w);
    m_periods->setObjectName(QStringLiteral("stepPeriods"));
    m_periods->setRange(1, StepTestSpec::kMaxPeriods);
    m_periods->setToolTip(tr("1: one step from FROM to TO. More: a square wave of that many "
                             "periods, each half held for the duration."));
    auto *range = new QHBoxLayout;
    range->addWidget(m_from, 1);
    range->addWidget(new QLabel(QStringLiteral("\u2192"), w));
    range->addWidget(m_to, 1);
    auto *timing = new QHBoxLayout;
    timing->addWidget(m_duration, 1);
    timing->addWidget(new QLabel(tr("periods"), w));
    timing->addWidget(m_periods);
    form->addRow(tr("Loop"), m_loop);
    form->addRow(tr("From \u2192 to"), range);
    form->addRow(tr("Each step"), timing);
    connect(m_loop, &QComboBox::currentIndexChanged, this, &StepTestPanel::loopChanged);
    loopChanged();
    return w;
}

void StepTestPanel::loopChanged()
{
    const bool speed = spec().loop == StepLoop::Speed;
    const QString unit = speed ? tr(" dps") : QStringLiteral("\u00b0");
    m_from->setSuffix(unit);
    m_to->setSuffix(unit);
    const QString tip = speed ? tr("Rotor speed. The drive is held at FROM before the step and "
                                   "goes back to FROM after it.")
                              : tr("Multi-turn rotor angle. Filled in from where the drive is; "
                                   "each target may be at most one output turn away.");
    m_from->setToolTip(tip);
    m_to->setToolTip(tip);
    if (speed) {
        m_from->setValue(0);
        m_to->setValue(kDefaultSpeedStepDps);
    } else {
        // Targets start where the drive is: never a made-up 0 for an unknown angle.
        const std::optional<double> here = m_sources.angleDeg ? m_sources.angleDeg() : std::nullopt;
        if (here) {
            m_from->setValue(std::round(*here));
            m_to->setValue(std::round(*here) + kDefaultPositionStepDeg);
        }
    }
}

void StepTestPanel::setDrive(const StepTestDrive &drive)
{
    const bool otherDrive = drive.id != m_drive.id || drive.session != m_drive.session;
    m_drive = drive;
    if (otherDrive && !isRunning()) {
        m_last.reset(); // "repeat" means this drive's last test, never another's
        if (spec().loop == StepLoop::Position)
            loopChanged(); // FROM follows the newly selected drive's angle
    }
    refreshEnabled();
}

StepTestSpec StepTestPanel::spec() const
{
    StepTestSpec s;
    s.id = m_drive.id;
    s.loop = StepLoop(m_loop->currentData().toInt());
    s.from = m_from->value();
    s.to = m_to->value();
    s.durationS = m_duration->value();
    s.periods = m_periods->value();
    s.preRollS = std::min(1.0, std::max(0.2, s.durationS));
    return s;
}

void StepTestPanel::setSpec(const StepTestSpec &s)
{
    m_loop->setCurrentIndex(m_loop->findData(int(s.loop)));
    m_from->setValue(s.from);
    m_to->setValue(s.to);
    m_duration->setValue(s.durationS);
    m_periods->setValue(s.periods);
}

bool StepTestPanel::runTest()
{
    return start(spec());
}

bool StepTestPanel::repeatLast()
{
    if (!canRepeat())
        return false;
    setSpec(*m_last);
    return start(*m_last);
}

bool StepTestPanel::canRepeat() const
{
    return m_last && m_last->id == m_drive.id && m_drive.canSend && !isRunning();
}

bool StepTestPanel::isRunning() const
{
    return m_runner && m_runner->isRunning();
}

void StepTestPanel::ensureRunner()
{
    if (m_runner && m_runnerSession == m_drive.session)
        return;
    m_runner.reset();
    m_runnerSession = m_drive.session;
    if (!m_drive.session)
        return;
    m_runner = std::make_unique<tuning::StepTestRunner>(*m_drive.session);
    connect(m_runner.get(), &tuning::StepTestRunner::finished, this, &StepTestPanel::onFinished);
    connect(m_runner.get(), &tuning::StepTestRunner::failed, this, &StepTestPanel::onFailed);
    connect(m_runner.get(), &tuning::StepTestRunner::started, this,
            [this](const tuning::StepTestPlan &plan) {
                m_pending.ranAt = QDateTime::currentDateTimeUtc();
                const QString bound =
                    plan.spec().loop == StepLoop::Position
                        ? tr(" Max speed %1 dps.").arg(Format::number(plan.boundDps(), 0))
                        : QString();
                setStatus(tr("Testing drive %1: %2 setpoints over %3 s.%4")
                              .arg(plan.spec().id)
                              .arg(plan.setpoints().size())
                              .arg(Format::number(plan.endS(), 1))
                              .arg(bound));
            });
}

bool StepTestPanel::start(const StepTestSpec &s)
{
    if (isRunning())
        return false;
    if (!m_drive.canSend || m_drive.id <= 0) {
        setStatus(tr("Nothing was sent: connect and select a drive first."), true);
        return false;
    }
    if (s.from == s.to) {
        setStatus(tr("Nothing was sent: FROM and TO are equal, there is no step."), true);
        return false;
    }
    QString why;
    const std::optional<safety::SoftLimits> limits =
        m_sources.limits ? m_sources.limits(&why) : std::nullopt;
    if (!limits) {
        setStatus(why.isEmpty() ? tr("Nothing was sent: no soft limits are in force.") : why, true);
        return false;
    }
    ensureRunner();
    if (!m_runner)
        return false;
    m_pending = tuning::StepRun{};
    m_pending.driveId = s.id;
    m_pending.series = m_drive.series ? protocol::seriesName(*m_drive.series) : QString();
    m_pending.model = m_drive.model;
    m_pending.generation = m_drive.generation;
    m_pending.spec = {s.loop, s.from, s.to, s.durationS, s.periods};
    m_pending.gains = m_sources.gains ? m_sources.gains() : QJsonObject{};
    m_pending.ramps = m_sources.ramps ? m_sources.ramps() : QJsonObject{};
    m_pending.effortLimit = m_sources.effortLimit ? m_sources.effortLimit() : std::nullopt;
    if (!m_runner->start(s, *limits, m_drive.gearRatio))
        return false;
    m_last = s;
    setStatus(tr("Reading where drive %1 is\u2026").arg(s.id));
    refreshEnabled();
    emit runningChanged(true);
    return true;
}

void StepTestPanel::halt(const QString &reason)
{
    if (!isRunning())
        return;
    m_runner->abort(); // ends with failed(Aborted): the status says what may still move
    Q_UNUSED(reason)
}

void StepTestPanel::onFinished(const StepTestResult &result)
{
    tuning::StepRun run = m_pending;
    run.trace = result.trace;
    const int key = m_runs->add(run);
    const int number = m_runs->find(key)->number;
    const tuning::EdgeMetrics m = m_runs->find(key)->stepMetrics();
    const bool power = run.trace.effortIsPower;
    setStatus(tr("Run %1: rise %2, overshoot %3, settling (2 %) %4; %5 samples at %6 Hz. %7")
                  .arg(number)
                  .arg(MetricText::value(m, StepMetricKind::RiseTime, run.spec.loop, power),
                       MetricText::value(m, StepMetricKind::Overshoot, run.spec.loop, power),
                       MetricText::value(m, StepMetricKind::Settling2, run.spec.loop, power))
                  .arg(m.samples)
                  .arg(Format::number(result.sampleRateHz, 0))
                  .arg(stillMoving(result)));
    refreshEnabled();
    emit runningChanged(false);
    emit runFinished(key);
}

void StepTestPanel::onFailed(const StepTestResult &result)
{
    setStatus(failureText(result), true);
    refreshEnabled();
    emit runningChanged(false);
}

QString StepTestPanel::failureText(const StepTestResult &result) const
{
    const QString moving = result.anythingSent() ? QLatin1Char(' ') + stillMoving(result)
                                                 : QLatin1Char(' ') + tr("Nothing was sent.");
    switch (result.failure) {
    case StepTestFailure::None:
        return {};
    case StepTestFailure::BadSpec:
        return tr("The test cannot run as set (%1).").arg(result.message) + moving;
    case StepTestFailure::Refused:
        // Worded as the Control view words a refusal (and as lkctl step prints it).
        return tr("Refused: %1.").arg(text::VerdictText::stepRefusal(result.refusal)) + moving;
    case StepTestFailure::Silent:
        return tr("Drive %1 did not answer: the test stopped.").arg(result.spec.id) + moving;
    case StepTestFailure::Disconnected:
        return tr("The link went down: the test stopped.") + moving;
    case StepTestFailure::Aborted:
        return tr("The test was stopped.") + moving;
    }
    return {};
}

QString StepTestPanel::stillMoving(const StepTestResult &result) const
{
    if (result.sent.isEmpty())
        return {};
    const tuning::StepSent &last = result.sent.last();
    if (result.spec.loop == StepLoop::Speed)
        return std::abs(last.setpoint.target) > 0
                   ? tr("Drive %1 was last told to turn at %2 dps and keeps doing so until "
                        "stopped.")
                         .arg(result.spec.id)
                         .arg(Format::number(last.setpoint.target, 0))
                   : tr("Drive %1 was last told to stand still (0 dps).").arg(result.spec.id);
    return tr("Drive %1 holds (or is moving to) %2\u00b0.")
        .arg(result.spec.id)
        .arg(Format::number(last.setpoint.target, 2));
}

void StepTestPanel::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, StatusColors::current())
              : QString());
}

QString StepTestPanel::statusText() const
{
    return m_status->text();
}

void StepTestPanel::refreshEnabled()
{
    const bool running = isRunning();
    m_run->setText(running ? tr("Stop (Esc)") : tr("Test step"));
    m_run->setToolTip(running ? tr("Emergency stop: Motor Off to every drive.")
                              : tr("Run the step test set above on the selected drive."));
    m_run->setEnabled(running || m_drive.canSend);
    m_repeat->setEnabled(canRepeat());
    for (QWidget *w : {static_cast<QWidget *>(m_loop), static_cast<QWidget *>(m_from),
                       static_cast<QWidget *>(m_to), static_cast<QWidget *>(m_duration),
                       static_cast<QWidget *>(m_periods)})
        w->setEnabled(!running);
}

} // namespace lk::ui
