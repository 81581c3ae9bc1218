#include "FrequencyResponseView.h"

#include "TuningRunGate.h"
#include "TuningView.h"

#include "ParameterFileText.h"

#include <bus/BusSession.h>
#include <panels/FileDialogs.h>
#include <panels/Format.h>
#include <panels/StatusColors.h>
#include <text/VerdictText.h>
#include <tuning/BodeChart.h>
#include <tuning/FrequencyRunFile.h>
#include <tuning/FrequencyRunList.h>
#include <tuning/StepRunsModel.h>

#include <QtGui/QStandardItemModel>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

using tuning::FrequencySweepPlan;
using tuning::FrequencySweepResult;
using tuning::FrequencySweepSpec;
using tuning::SweepLoop;

namespace {
constexpr double kPositionAmplitudeDeg = 5; // a few degrees: well inside most windows
}

FrequencyResponseView::FrequencyResponseView(TuningView *host, QWidget *parent)
    : QWidget(parent), m_host(host), m_runs(new FrequencyRunList(this))
{
    setObjectName(QStringLiteral("frequencyResponse"));
    m_chart = new BodeChart(this);
    m_travel = new QLabel(this);
    m_travel->setObjectName(QStringLiteral("sweepTravel"));
    m_travel->setWordWrap(true);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("sweepStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_run = new QPushButton(tr("Measure"), this);
    m_run->setObjectName(QStringLiteral("runSweep"));
    m_clear = new QPushButton(tr("Clear runs"), this);
    m_clear->setObjectName(QStringLiteral("clearSweeps"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_run);
    buttons->addWidget(m_clear);
    buttons->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildFields());
    layout->addWidget(m_travel);
    layout->addLayout(buttons);
    layout->addLayout(buildRunButtons());
    layout->addWidget(m_status);
    layout->addWidget(m_chart, 1);
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (isRunning())
            halt();
        else
            runSweep();
    });
    connect(m_clear, &QPushButton::clicked, m_runs, &FrequencyRunList::clear);
    connect(m_runs, &FrequencyRunList::changed, this, &FrequencyResponseView::refreshChart);
    // The host's read is what lets a sweep run: refresh when one ends.
    connect(m_host, &TuningView::parametersRead, this, &FrequencyResponseView::refresh);
    setStatus(tr("Measures the speed loop's frequency response: a sine of the speed setpoint "
                 "around the operating point, one frequency after the other. Its extremes are "
                 "checked against the soft limits (Control view) before anything moves; Esc "
                 "stops the motor and puts the gains read back. The position loop's is offered "
                 "while an angle range is set: a sine of the angle around where the drive is."));
    refreshChart();
    // Not refresh(): the host builds its widgets before its read cycle; showEvent() asks it.
    m_run->setEnabled(false);
}

FrequencyResponseView::~FrequencyResponseView() = default;

void FrequencyResponseView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    refresh();
}

QWidget *FrequencyResponseView::buildFields()
{
    auto *w = new QWidget(this);
    auto *form = new QFormLayout(w);
    form->setContentsMargins(0, 0, 0, 0);
    auto spin = [w](const QString &name, double min, double max, int decimals, double value,
                    const QString &suffix) {
        auto *s = new QDoubleSpinBox(w);
        s->setObjectName(name);
        s->setRange(min, max);
        s->setDecimals(decimals);
        s->setValue(value);
        s->setSuffix(suffix);
        s->setKeyboardTracking(false);
        s->setMinimumWidth(70);
        return s;
    };
    const FrequencySweepSpec d;
    m_loop = new QComboBox(w);
    m_loop->setObjectName(QStringLiteral("sweepLoop"));
    m_loop->addItem(tr("Speed loop"), int(SweepLoop::Speed));
    m_loop->addItem(tr("Position loop"), int(SweepLoop::Position));
    m_loop->setToolTip(tr("The position loop needs an angle range (Control view): its sine "
                          "stays inside it, around where the drive is."));
    form->addRow(tr("Loop"), m_loop);
    // The soft limits bound the speeds, not the boxes.
    m_centre = spin(QStringLiteral("sweepCentre"), -1e5, 1e5, 0, 2 * d.amplitude, tr(" dps"));
    m_centre->setToolTip(tr("The speed the sine is centred on. Away from 0, so that the rotor "
                            "never stops: friction would bend the response."));
    m_amplitude = spin(QStringLiteral("sweepAmplitude"), 1, 1e5, 0, d.amplitude, tr(" dps"));
    m_amplitude->setToolTip(tr("The sine's peak around the operating point."));
    m_from = spin(QStringLiteral("sweepFrom"), FrequencySweepSpec::kMinHz,
                  FrequencySweepSpec::kMaxHz, 1, d.fromHz, tr(" Hz"));
    m_to = spin(QStringLiteral("sweepTo"), FrequencySweepSpec::kMinHz, FrequencySweepSpec::kMaxHz,
                1, d.toHz, tr(" Hz"));
    m_points = new QSpinBox(w);
    m_points->setObjectName(QStringLiteral("sweepPoints"));
    m_points->setRange(1, FrequencySweepSpec::kMaxPoints);
    m_points->setValue(d.points);
    m_perPoint = spin(QStringLiteral("sweepPerPoint"), 0.1, 60, 1, d.minPointS, tr(" s"));
    m_perPoint->setToolTip(tr("Each frequency lasts at least this long (and 5 cycles)."));
    auto row = [w](QWidget *a, const QString &between, QWidget *b) {
        auto *h = new QHBoxLayout;
        h->addWidget(a, 1);
        h->addWidget(new QLabel(between, w));
        h->addWidget(b, 1);
        return h;
    };
    form->addRow(tr("Operating point \u00b1 amplitude"),
                 row(m_centre, QStringLiteral("\u00b1"), m_amplitude));
    form->addRow(tr("From \u2192 to"), row(m_from, QStringLiteral("\u2192"), m_to));
    form->addRow(tr("Frequencies, each at least"), row(m_points, QString(), m_perPoint));
    for (QDoubleSpinBox *s : {m_centre, m_amplitude, m_from, m_to, m_perPoint})
        connect(s, &QDoubleSpinBox::valueChanged, this, &FrequencyResponseView::refresh);
    connect(m_points, &QSpinBox::valueChanged, this, &FrequencyResponseView::refresh);
    connect(m_loop, &QComboBox::currentIndexChanged, this, &FrequencyResponseView::onLoopChosen);
    return w;
}

SweepLoop FrequencyResponseView::loop() const
{
    return SweepLoop(m_loop->currentData().toInt());
}

bool FrequencyResponseView::positionOffered() const
{
    const auto *model = qobject_cast<const QStandardItemModel *>(m_loop->model());
    return model && model->item(1)->isEnabled();
}

bool FrequencyResponseView::setLoop(SweepLoop loop)
{
    if (loop == SweepLoop::Position && !positionOffered())
        return false;
    m_loop->setCurrentIndex(loop == SweepLoop::Position ? 1 : 0);
    return true;
}

void FrequencyResponseView::onLoopChosen()
{
    // The amplitude's unit follows the loop; a position sine is centred where the drive is.
    const bool position = loop() == SweepLoop::Position;
    const QSignalBlocker block(m_amplitude);
    m_amplitude->setSuffix(position ? tr(" deg") : tr(" dps"));
    m_amplitude->setDecimals(position ? 1 : 0);
    m_amplitude->setValue(position ? kPositionAmplitudeDeg : FrequencySweepSpec{}.amplitude);
    m_centre->setVisible(!position);
    refreshChart();
    refresh();
}

FrequencySweepPlan FrequencyResponseView::planFor(const FrequencySweepSpec &spec,
                                                  const TuningRunDrive &drive)
{
    FrequencySweepSpec planned = spec;
    // A position sweep's centre is read when it starts: planned in the window's middle.
    if (spec.loop == SweepLoop::Position && TuningRunGate::hasAngleWindow(drive.limits))
        planned.operatingPoint = (*drive.limits.minAngleDeg + *drive.limits.maxAngleDeg) / 2;
    return FrequencySweepPlan::make(planned, drive.series, drive.limits);
}

QString FrequencyResponseView::refusedText(const FrequencySweepSpec &spec, double value,
                                           const safety::Verdict &verdict) const
{
    const bool angle = spec.loop == SweepLoop::Position &&
                       verdict.kind != safety::LimitKind::SoftSpeed &&
                       verdict.kind != safety::LimitKind::SeriesSpeed;
    return (angle ? tr("Refused at %1\u00b0: %2.") : tr("Refused at %1 dps: %2."))
        .arg(Format::number(value, angle ? 2 : 0),
             text::VerdictText::verdict(verdict, m_host->series()));
}

QVBoxLayout *FrequencyResponseView::buildRunButtons()
{
    m_runPick = new QComboBox(this);
    m_runPick->setObjectName(QStringLiteral("sweepRunPick"));
    // Short, and never grown by its entries: the list shows a run's whole legend when it opens,
    // and the Tuning view must fit a 1366-pixel screen beside the gains.
    m_runPick->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_runPick->setMinimumContentsLength(12);
    m_save = new QPushButton(tr("Save run\u2026"), this);
    m_save->setObjectName(QStringLiteral("saveSweepRun"));
    m_open = new QPushButton(tr("Open run\u2026"), this);
    m_open->setObjectName(QStringLiteral("openSweepRun"));
    m_remove = new QPushButton(tr("Remove run"), this);
    m_remove->setObjectName(QStringLiteral("removeSweepRun"));
    m_remove->setToolTip(tr("Take the chosen run off the chart (a saved file stays)."));
    // The list above its buttons: in one row they set the Tuning view's narrowest width.
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_save);
    buttons->addWidget(m_open);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    auto *row = new QVBoxLayout;
    row->addWidget(m_runPick);
    row->addLayout(buttons);
    connect(m_remove, &QPushButton::clicked, this, [this] { m_runs->remove(chosenRun()); });
    connect(m_save, &QPushButton::clicked, this, [this] {
        const FrequencyRun *run = m_runs->find(chosenRun());
        if (!run)
            return;
        const QString path = FileDialogs::saveFile(
            this, FileDialogs::Purpose::StepRuns, tr("Save frequency run"),
            FileDialogs::suggestedName(QStringLiteral("frequency-run"), {run->driveId}, run->ranAt,
                                       QLatin1String(tuning::FrequencyRunFile::kSuffix)),
            tr("Frequency runs (*%1)").arg(QLatin1String(tuning::FrequencyRunFile::kSuffix)));
        if (!path.isEmpty())
            saveRun(chosenRun(), path);
    });
    connect(m_open, &QPushButton::clicked, this, [this] {
        const QString path =
            FileDialogs::openFile(this, FileDialogs::Purpose::StepRuns, tr("Open frequency run"),
                                  tr("Frequency runs (*%1);;All files (*)")
                                      .arg(QLatin1String(tuning::FrequencyRunFile::kSuffix)));
        if (!path.isEmpty())
            openRun(path);
    });
    return row;
}

int FrequencyResponseView::chosenRun() const
{
    return m_runPick->currentData().toInt();
}

bool FrequencyResponseView::saveRun(int key, const QString &path)
{
    const FrequencyRun *run = m_runs->find(key);
    if (!run)
        return false;
    const QString failed = tuning::FrequencyRunFile::save(path, *run);
    if (!failed.isEmpty()) {
        setStatus(tr("%1 was not saved: %2").arg(m_runs->title(m_runs->indexOf(key)), failed),
                  true);
        return false;
    }
    setStatus(tr("%1 saved to %2.").arg(m_runs->title(m_runs->indexOf(key)), path));
    return true;
}

bool FrequencyResponseView::openRun(const QString &path)
{
    record::ParameterFileError error;
    const std::optional<FrequencyRun> run = tuning::FrequencyRunFile::load(path, &error);
    if (!run) {
        // A word of a fixed list ("loop", a dropped frequency's "reason") says which words.
        const QString why =
            error.kind == record::ParameterFileError::Kind::WrongType && !error.detail.isEmpty()
                ? tr("%1 is %2: it must be %3").arg(error.key, error.found, error.detail)
                : ParameterFileText::describe(error);
        setStatus(tr("%1 was not opened: %2").arg(path, why), true);
        return false;
    }
    const int key = m_runs->addLoaded(*run, path);
    // Only runs of the loop chosen share the axes: show the loaded run's, where offered.
    if (run->spec.loop != loop() && !setLoop(run->spec.loop)) {
        setStatus(tr("%1 is a position loop's response: it is shown when the position loop is "
                     "chosen (an angle range is set).")
                      .arg(m_runs->title(m_runs->indexOf(key))));
        return true;
    }
    setStatus(tr("Opened %1.").arg(m_runs->title(m_runs->indexOf(key))));
    return true;
}

QString FrequencyResponseView::legendText(int key) const
{
    const int i = m_runs->indexOf(key);
    if (i < 0)
        return {};
    const FrequencyRun &run = m_runs->runs().at(i);
    const bool position = run.spec.loop == SweepLoop::Position;
    QString gains = tr("gains unknown");
    if (run.gains) {
        const tuning::PidTriple &g = position ? run.gains->angle : run.gains->speed;
        gains = tr("Kp %1 Ki %2 Kd %3").arg(g.kp).arg(g.ki).arg(g.kd);
    }
    return tr("%1: drive %2, %3, %4, %5")
        .arg(m_runs->title(i))
        .arg(run.driveId)
        .arg(position ? tr("position loop") : tr("speed loop"), gains,
             run.ranAt.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")));
}

void FrequencyResponseView::refreshRunPick()
{
    // The chosen run stays chosen; a run just added (measured or opened) becomes the choice.
    const int chosen = chosenRun();
    const bool added = m_runs->runs().size() > m_runPick->count();
    const QSignalBlocker block(m_runPick);
    m_runPick->clear();
    for (int i = 0; i < m_runs->runs().size(); ++i)
        m_runPick->addItem(legendText(m_runs->keyAt(i)), m_runs->keyAt(i));
    const int at = m_runPick->findData(chosen);
    m_runPick->setCurrentIndex(at >= 0 && !added ? at : m_runPick->count() - 1);
    const bool any = m_runPick->count() > 0;
    m_save->setEnabled(any);
    m_remove->setEnabled(any && !isRunning());
}

FrequencySweepSpec FrequencyResponseView::spec() const
{
    FrequencySweepSpec s;
    s.id = m_host->driveId();
    s.loop = loop();
    if (s.loop == SweepLoop::Speed)
        s.operatingPoint = m_centre->value(); // a position sweep's is read from the drive
    s.amplitude = m_amplitude->value();
    s.fromHz = m_from->value();
    s.toHz = m_to->value();
    s.points = m_points->value();
    s.minPointS = m_perPoint->value();
    return s;
}

void FrequencyResponseView::setSpec(const FrequencySweepSpec &s)
{
    setLoop(s.loop);
    if (s.loop == SweepLoop::Speed)
        m_centre->setValue(s.centre());
    m_amplitude->setValue(s.amplitude);
    m_from->setValue(s.fromHz);
    m_to->setValue(s.toHz);
    m_points->setValue(s.points);
    m_perPoint->setValue(s.minPointS);
}

QString FrequencyResponseView::travelText() const
{
    const FrequencySweepSpec s = spec();
    const std::optional<TuningRunDrive> drive = TuningRunGate::check(*m_host, s.loop, nullptr);
    if (!drive)
        return {};
    const FrequencySweepPlan plan = planFor(s, *drive);
    if (s.loop == SweepLoop::Position) // the centre is read when it starts: the sine's size
        return TuningRunGate::positionTravelText(*drive, s.amplitude, s.peakSpeedDps(),
                                                 plan.endS());
    if (!plan.allowed())
        return {};
    return TuningRunGate::travelText(*drive, s.centre() - s.amplitude, s.centre() + s.amplitude,
                                     plan.endS());
}

bool FrequencyResponseView::runSweep()
{
    if (isRunning())
        return false;
    QString why;
    const FrequencySweepSpec s = spec();
    const bool position = s.loop == SweepLoop::Position;
    const std::optional<TuningRunDrive> drive = TuningRunGate::check(*m_host, s.loop, &why);
    if (!drive) {
        setStatus(why, true);
        return false;
    }
    // The same plan the runner makes: a refusal names the limit before the question. A
    // position sweep's centre is read when it starts; the runner checks its extremes from
    // there, its peak speed is checked here already.
    const FrequencySweepPlan plan = planFor(s, *drive);
    const bool angleRefusal = position && !plan.allowed() && !plan.verdict().allowed() &&
                              plan.verdict().kind != safety::LimitKind::SoftSpeed &&
                              plan.verdict().kind != safety::LimitKind::SeriesSpeed;
    if (!plan.allowed() && !angleRefusal) {
        setStatus(
            plan.verdict().allowed()
                ? tr("The sweep cannot run as set (%1). Nothing was sent.").arg(plan.specError())
                : refusedText(s, plan.refusedDps(), plan.verdict()) + QLatin1Char(' ') +
                      tr("Nothing was sent."),
            true);
        return false;
    }
    const QString travel =
        position
            ? TuningRunGate::positionTravelText(*drive, s.amplitude, s.peakSpeedDps(), plan.endS())
            : TuningRunGate::travelText(*drive, s.centre() - s.amplitude, s.centre() + s.amplitude,
                                        plan.endS());
    if (!TuningRunGate::askFreeToTurn(this, *drive,
                                      position ? QStringLiteral("frequency_sweep_position")
                                               : QStringLiteral("frequency_sweep"),
                                      tr("Frequency response"), travel)) {
        setStatus(tr("Cancelled: nothing was sent."));
        return false;
    }
    // The question ran an event loop: the drive or the link may have changed meanwhile.
    if (!TuningRunGate::check(*m_host, s.loop, &why) || m_host->driveId() != drive->id) {
        setStatus(tr("The drive or the connection changed: nothing was sent."), true);
        return false;
    }
    ensureRunner(drive->session);
    if (!m_runner || !m_runner->start(s, drive->limits))
        return false;
    m_runningModel = drive->model;
    setStatus((position ? tr("Reading the gains and angle of drive %1\u2026")
                        : tr("Reading the gains and speed of drive %1\u2026"))
                  .arg(drive->id));
    refresh();
    emit runningChanged(true);
    return true;
}

void FrequencyResponseView::ensureRunner(bus::BusSession *session)
{
    if (m_runner && m_runnerSession == session)
        return;
    m_runner.reset();
    m_runnerSession = session;
    if (!session)
        return;
    m_runner = std::make_unique<tuning::FrequencySweepRunner>(*session);
    connect(m_runner.get(), &tuning::FrequencySweepRunner::finished, this,
            &FrequencyResponseView::onFinished);
    connect(m_runner.get(), &tuning::FrequencySweepRunner::failed, this,
            &FrequencyResponseView::onFailed);
    connect(m_runner.get(), &tuning::FrequencySweepRunner::started, this,
            [this](const FrequencySweepPlan &plan) {
                setStatus(tr("Sweeping drive %1: %2 frequencies over %3 s. Esc stops it.")
                              .arg(plan.spec().id)
                              .arg(plan.segments().size())
                              .arg(Format::number(plan.endS(), 1)));
            });
}

void FrequencyResponseView::halt()
{
    if (isRunning())
        m_runner->abort(); // ends with failed(Aborted): the status says what the drive does
}

bool FrequencyResponseView::isRunning() const
{
    return m_runner && m_runner->isRunning();
}

void FrequencyResponseView::onFinished(const FrequencySweepResult &result)
{
    FrequencyRun run;
    run.ranAt = QDateTime::currentDateTimeUtc();
    run.driveId = result.spec.id;
    run.series = m_host->series() ? protocol::seriesName(*m_host->series()) : QString();
    run.model = m_runningModel;
    run.spec = result.spec;
    run.gains = result.gains;
    run.response = result.response;
    const int key = m_runs->add(run);
    const QString title = m_runs->title(m_runs->indexOf(key));
    setStatus(tr("%1 points at %2 samples/s. %3 %4")
                  .arg(result.response.points.size())
                  .arg(Format::number(result.response.sampleRateHz, 0),
                       BodeChart::figuresLine(title, result.response),
                       TuningRunGate::endedText(result.outcome, result.spec.id)));
    refresh();
    emit runningChanged(false);
}

void FrequencyResponseView::onFailed(const FrequencySweepResult &result)
{
    QString text = TuningRunGate::failureText(result.failure, result.outcome, result.spec.id);
    if (result.failure == tuning::StepTestFailure::Refused && !result.refusal.allowed())
        text =
            refusedText(result.spec, result.refusedDps, result.refusal) + QLatin1Char(' ') + text;
    setStatus(text, true);
    refresh();
    emit runningChanged(false);
}

void FrequencyResponseView::refreshChart()
{
    QVector<BodeRun> shown;
    const QVector<FrequencyRun> runs = m_runs->shownRuns();
    const QVector<int> keys = m_runs->shownKeys();
    // Only comparable runs share the axes: the loop chosen, its unit.
    for (int i = 0; i < runs.size(); ++i)
        if (runs.at(i).spec.loop == loop())
            shown.append(
                {legendText(keys.at(i)), StepRunsModel::runColor(keys.at(i)), runs.at(i).response});
    m_chart->setRuns(shown);
    m_clear->setEnabled(!m_runs->runs().isEmpty() && !isRunning());
    refreshRunPick();
}

void FrequencyResponseView::refresh()
{
    const bool running = isRunning();
    m_run->setText(running ? tr("Stop (Esc)") : tr("Measure"));
    m_run->setToolTip(running ? tr("Stop at once: Motor Off, and the gains read back to RAM.")
                              : tr("Measure the frequency response set above on the selected "
                                   "drive (asks first)."));
    m_run->setEnabled(running || (m_host->canSendToDrive() && m_host->readComplete()));
    // The position loop is offered while an angle window is set.
    if (auto *model = qobject_cast<QStandardItemModel *>(m_loop->model())) {
        const bool offered =
            TuningRunGate::positionOffered(*m_host) || (running && loop() == SweepLoop::Position);
        model->item(1)->setEnabled(offered);
        if (!offered && loop() == SweepLoop::Position)
            m_loop->setCurrentIndex(0); // refresh() again, through onLoopChosen()
    }
    for (QWidget *w : {static_cast<QWidget *>(m_loop), static_cast<QWidget *>(m_centre),
                       static_cast<QWidget *>(m_amplitude), static_cast<QWidget *>(m_from),
                       static_cast<QWidget *>(m_to), static_cast<QWidget *>(m_points),
                       static_cast<QWidget *>(m_perPoint)})
        w->setEnabled(!running);
    m_clear->setEnabled(!m_runs->runs().isEmpty() && !running);
    if (!running)
        m_travel->setText(travelText());
}

void FrequencyResponseView::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, StatusColors::current())
              : QString());
}

QString FrequencyResponseView::statusText() const
{
    return m_status->text();
}

} // namespace lk::ui
