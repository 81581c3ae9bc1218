#include "GainSearchView.h"

#include "GainSearchViewComparison.h"
#include "GainSearchViewOutcome.h"
#include "ParameterTable.h"
#include "TuningRunGate.h"
#include "TuningView.h"

#include <bus/BusSession.h>
#include <panels/Format.h>
#include <panels/StatusColors.h>
#include <tuning/MetricText.h>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

using tuning::CandidateScore;
using tuning::CandidateVerdict;
using tuning::GainSearchResult;
using tuning::GainSearchSpec;
using tuning::StepLoop;

namespace {

enum Column { Number, Kp, Ki, Rise, Overshoot, ErrorArea, Verdict, kColumns };

/// How far a search may turn the axis: every candidate's pre-roll and square, at most, and its
/// Bode step.
QString searchTravel(const TuningRunDrive &drive, const GainSearchSpec &s)
{
    const double seconds =
        s.maxCandidates * (s.preRollS + 2 * s.periods * s.stepS) +
        (s.measureBode ? s.bodeSeconds(drive.series, drive.limits).value_or(0) : 0);
    // Position: steps of `to` from where the drive is, at most the speed limit fast.
    if (s.loop == StepLoop::Position)
        return TuningRunGate::positionTravelText(drive, std::abs(s.to), drive.limits.maxSpeedDps,
                                                 seconds);
    return TuningRunGate::travelText(drive, std::min(s.from, s.to), std::max(s.from, s.to),
                                     seconds);
}

tuning::SweepLoop gateLoop(StepLoop loop)
{
    return loop == StepLoop::Position ? tuning::SweepLoop::Position : tuning::SweepLoop::Speed;
}

int fieldIndex(const ParamSetSpec &spec, const QString &key)
{
    const QVector<ParamField> fields = spec.fields();
    for (int i = 0; i < fields.size(); ++i) {
        if (fields.at(i).key == key)
            return i;
    }
    return -1;
}

} // namespace

QString GainSearchView::verdictText(CandidateVerdict v)
{
    switch (v) {
    case CandidateVerdict::Accepted:
        return tr("within the bounds");
    case CandidateVerdict::Overshoot:
        return tr("overshoots");
    case CandidateVerdict::Oscillates:
        return tr("oscillates");
    case CandidateVerdict::NotSettled:
        return tr("did not settle");
    case CandidateVerdict::Saturated:
        return tr("current at its limit: unstable, search stopped");
    case CandidateVerdict::Growing:
        return tr("swings growing: unstable, search stopped");
    }
    return {};
}

QString GainSearchView::loopGainName(StepLoop loop)
{
    return loop == StepLoop::Position ? tr("Angle") : tr("Speed");
}

QString GainSearchView::riseText(const CandidateScore &s)
{
    return MetricText::value(s.metrics, StepMetricKind::RiseTime, s.trace.loop, false);
}

QString GainSearchView::overshootText(const CandidateScore &s)
{
    return MetricText::value(s.metrics, StepMetricKind::Overshoot, s.trace.loop, false);
}

GainSearchView::GainSearchView(TuningView *host, QWidget *parent) : QWidget(parent), m_host(host)
{
    setObjectName(QStringLiteral("gainSearch"));
    m_travel = new QLabel(this);
    m_travel->setObjectName(QStringLiteral("searchTravel"));
    m_travel->setWordWrap(true);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("searchStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_run = new QPushButton(tr("Search gains"), this);
    m_run->setObjectName(QStringLiteral("runSearch"));
    m_writeRam = new QPushButton(tr("Write to RAM"), this);
    m_writeRam->setObjectName(QStringLiteral("writeSuggestedRam"));
    m_writeRam->setToolTip(tr("Write the suggested Kp and Ki to the drive's RAM (lost at "
                              "power-off), then read back. Nothing is written before this."));
    m_writeRom = new QPushButton(tr("Write to ROM\u2026"), this);
    m_writeRom->setObjectName(QStringLiteral("writeSuggestedRom"));
    m_writeRom->setToolTip(tr("Keep the suggested gains written to RAM: asks first, then writes "
                              "them to ROM."));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_run);
    buttons->addStretch(1);
    buttons->addWidget(m_writeRam);
    buttons->addWidget(m_writeRom);

    m_table = new QTableWidget(0, kColumns, this);
    m_table->setObjectName(QStringLiteral("candidateTable"));
    m_table->setHorizontalHeaderLabels({tr("#"), tr("Kp"), tr("Ki"), tr("Rise"), tr("Overshoot"),
                                        tr("Error area"), tr("Verdict")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildFields());
    layout->addWidget(m_travel);
    layout->addLayout(buttons);
    layout->addWidget(m_status);
    layout->addWidget(m_table, 1);
    m_compare = new GainSearchViewComparison(this);
    layout->addWidget(m_compare, 2);
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (isRunning())
            halt();
        else
            runSearch();
    });
    connect(m_writeRam, &QPushButton::clicked, this, &GainSearchView::writeBestToRam);
    connect(m_writeRom, &QPushButton::clicked, this, &GainSearchView::writeBestToRom);
    connect(m_host, &TuningView::parametersRead, this, &GainSearchView::refresh);
    setStatus(tr("Tries speed-loop gains (or, with an angle window, position-loop gains) with "
                 "short steps within the soft limits and suggests the fastest whose overshoot "
                 "stays under the bound. Nothing is kept in the drive: the gains read go back to "
                 "RAM at the end."));
    // Not refresh(): the host builds its widgets before its read cycle; showEvent() asks it.
    m_run->setEnabled(false);
    m_writeRam->setEnabled(false);
    m_writeRom->setEnabled(false);
}

void GainSearchView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    refresh();
}

GainSearchView::~GainSearchView() = default;

QWidget *GainSearchView::buildFields()
{
    auto *w = new QWidget(this);
    auto *form = new QFormLayout(w);
    m_form = form;
    form->setContentsMargins(0, 0, 0, 0);
    const GainSearchSpec d;
    auto spin = [w](const QString &name, double min, double max, double value,
                    const QString &suffix) {
        auto *s = new QDoubleSpinBox(w);
        s->setObjectName(name);
        s->setRange(min, max);
        s->setDecimals(0);
        s->setValue(value);
        s->setSuffix(suffix);
        s->setKeyboardTracking(false);
        s->setMinimumWidth(70);
        return s;
    };
    m_overshoot = spin(QStringLiteral("maxOvershoot"), 0, 100, d.maxOvershootPct, tr(" %"));
    m_overshoot->setToolTip(tr("A candidate whose step overshoots more than this is not "
                               "suggested."));
    m_from = spin(QStringLiteral("searchFrom"), -1e5, 1e5, d.from, tr(" dps"));
    m_to = spin(QStringLiteral("searchTo"), -1e5, 1e5, d.to, tr(" dps"));
    m_from->setToolTip(tr("Each candidate steps the speed between these two, away from 0 where "
                          "friction would bend the steps."));
    m_to->setToolTip(m_from->toolTip());
    m_loop = new QComboBox(w);
    m_loop->setObjectName(QStringLiteral("searchLoop"));
    m_loop->addItem(tr("Speed loop"), int(StepLoop::Speed));
    m_loop->addItem(tr("Position loop"), int(StepLoop::Position));
    m_loop->setToolTip(tr("The position loop is offered while an angle range (both ends) is "
                          "set: its steps go from the angle the drive is at and back, inside "
                          "the range."));
    m_step =
        spin(QStringLiteral("searchStep"), 0.5, 180, GainSearchSpec::kPositionStepDeg, tr(" deg"));
    m_step->setDecimals(1);
    m_step->setToolTip(tr("Each candidate steps the angle this far from where the drive is and "
                          "back (down when the range has no room above)."));
    m_maxCandidates = new QSpinBox(w);
    m_maxCandidates->setObjectName(QStringLiteral("maxCandidates"));
    m_maxCandidates->setRange(1, 50);
    m_maxCandidates->setValue(d.maxCandidates);
    auto *steps = new QHBoxLayout;
    m_speedSteps = steps;
    steps->addWidget(m_from, 1);
    steps->addWidget(new QLabel(QStringLiteral("\u2194"), w));
    steps->addWidget(m_to, 1);
    form->addRow(tr("Loop"), m_loop);
    form->addRow(tr("Max overshoot"), m_overshoot);
    form->addRow(tr("Steps between"), steps);
    form->addRow(tr("Step size"), m_step);
    form->addRow(tr("Candidates at most"), m_maxCandidates);
    // On by default here (the issue's "best beside the current gains (step overlay and Bode)"),
    // off in lkctl: it adds two sweeps.
    m_measureBode = new QCheckBox(tr("Measure the Bode of both"), w);
    m_measureBode->setObjectName(QStringLiteral("measureBode"));
    m_measureBode->setChecked(true);
    m_measureBode->setToolTip(tr("After the search, measure the speed loop's frequency response "
                                 "with the gains read and with the suggested gains (written to "
                                 "RAM for that sweep only, the gains read put back after it)."));
    form->addRow(QString(), m_measureBode);
    connect(m_measureBode, &QCheckBox::toggled, this, &GainSearchView::refresh);
    for (QDoubleSpinBox *s : {m_overshoot, m_from, m_to, m_step})
        connect(s, &QDoubleSpinBox::valueChanged, this, &GainSearchView::refresh);
    connect(m_loop, &QComboBox::currentIndexChanged, this, &GainSearchView::refresh);
    connect(m_maxCandidates, &QSpinBox::valueChanged, this, &GainSearchView::refresh);
    return w;
}

StepOverlayChart *GainSearchView::overlay() const
{
    return m_compare->overlay();
}

BodeChart *GainSearchView::bode() const
{
    return m_compare->bode();
}

StepLoop GainSearchView::loop() const
{
    return StepLoop(m_loop->currentData().toInt());
}

GainSearchSpec GainSearchView::spec() const
{
    const bool position = loop() == StepLoop::Position;
    GainSearchSpec s = position ? GainSearchSpec::forPosition(m_host->driveId()) : GainSearchSpec{};
    s.id = m_host->driveId();
    s.maxOvershootPct = m_overshoot->value();
    if (position) {
        s.to = m_step->value();
    } else {
        s.from = m_from->value();
        s.to = m_to->value();
        s.measureBode = m_measureBode->isChecked(); // the Bode step is the speed loop's
    }
    s.maxCandidates = m_maxCandidates->value();
    return s;
}

void GainSearchView::setSpec(const GainSearchSpec &s)
{
    m_loop->setCurrentIndex(m_loop->findData(int(s.loop)));
    m_overshoot->setValue(s.maxOvershootPct);
    if (s.loop == StepLoop::Position) {
        m_step->setValue(std::abs(s.to));
    } else {
        m_from->setValue(s.from);
        m_to->setValue(s.to);
    }
    m_maxCandidates->setValue(s.maxCandidates);
    m_measureBode->setChecked(s.measureBode);
}

bool GainSearchView::runSearch()
{
    if (isRunning())
        return false;
    QString why;
    const GainSearchSpec s = spec();
    const std::optional<TuningRunDrive> drive =
        TuningRunGate::check(*m_host, gateLoop(s.loop), &why);
    if (!drive) {
        setStatus(why, true);
        return false;
    }
    if (s.measureBode && !s.bodeSeconds(drive->series, drive->limits)) {
        setStatus(tr("The Bode of both is refused within these limits: clear the box or change "
                     "the steps. Nothing was sent."),
                  true);
        return false;
    }
    const QString travel = searchTravel(*drive, s);
    const QString key = s.loop == StepLoop::Position ? QStringLiteral("gain_search_position")
                                                     : QStringLiteral("gain_search");
    if (!TuningRunGate::askFreeToTurn(this, *drive, key, tr("Suggested gains"), travel)) {
        setStatus(tr("Cancelled: nothing was sent."));
        return false;
    }
    if (!TuningRunGate::check(*m_host, gateLoop(s.loop), &why) || m_host->driveId() != drive->id) {
        setStatus(tr("The drive or the connection changed: nothing was sent."), true);
        return false;
    }
    ensureRunner(drive->session);
    if (!m_runner || !m_runner->start(s, drive->limits))
        return false;
    m_result.reset();
    m_ramWritten = false;
    m_searchedId = drive->id;
    m_table->setRowCount(0);
    m_compare->show(m_result);
    setStatus(
        s.loop == StepLoop::Position
            ? tr("Searching the position-loop gains of drive %1\u2026 Esc stops it.").arg(drive->id)
            : tr("Searching the speed-loop gains of drive %1\u2026 Esc stops it.").arg(drive->id));
    refresh();
    emit runningChanged(true);
    return true;
}

void GainSearchView::ensureRunner(bus::BusSession *session)
{
    if (m_runner && m_runnerSession == session)
        return;
    m_runner.reset();
    m_runnerSession = session;
    if (!session)
        return;
    m_runner = std::make_unique<tuning::GainSearchRunner>(*session);
    connect(m_runner.get(), &tuning::GainSearchRunner::candidateScored, this,
            &GainSearchView::onScored);
    connect(m_runner.get(), &tuning::GainSearchRunner::bodeSweepStarted, this,
            &GainSearchView::onBodeSweep);
    connect(m_runner.get(), &tuning::GainSearchRunner::finished, this, &GainSearchView::onEnded);
    connect(m_runner.get(), &tuning::GainSearchRunner::failed, this, &GainSearchView::onEnded);
}

void GainSearchView::halt()
{
    if (isRunning())
        m_runner->abort(); // ends with failed(Aborted)
}

bool GainSearchView::isRunning() const
{
    return m_runner && m_runner->isRunning();
}

void GainSearchView::fillRow(int row, const CandidateScore &score)
{
    const tuning::PidTriple &gains =
        tuning::GainSearchStrategy::tuned(score.gains, score.trace.loop);
    const QStringList cells{row == 0 ? tr("read") : QString::number(row),
                            QString::number(gains.kp),
                            QString::number(gains.ki),
                            riseText(score),
                            overshootText(score),
                            tr("%1 s").arg(Format::number(score.errorAreaS, 4)),
                            verdictText(score.verdict)};
    for (int c = 0; c < kColumns; ++c)
        m_table->setItem(row, c, new QTableWidgetItem(cells.at(c)));
}

void GainSearchView::onScored(const CandidateScore &score, int index)
{
    if (m_table->rowCount() <= index)
        m_table->setRowCount(index + 1);
    fillRow(index, score);
    m_table->scrollToItem(m_table->item(index, 0));
    setStatus(tr("Candidate %1 of at most %2 tried on drive %3\u2026 Esc stops it.")
                  .arg(index + 1)
                  .arg(m_maxCandidates->value())
                  .arg(m_searchedId));
}

void GainSearchView::onBodeSweep(bool best, double seconds)
{
    setStatus(best ? tr("Measuring the Bode of the suggested gains on drive %1 (in RAM for this "
                        "sweep only, %2 s)\u2026 Esc stops it.")
                         .arg(m_searchedId)
                         .arg(Format::number(seconds, 0))
                   : tr("Measuring the Bode of the gains read on drive %1 (%2 s)\u2026 Esc "
                        "stops it.")
                         .arg(m_searchedId)
                         .arg(Format::number(seconds, 0)));
}

void GainSearchView::onEnded(const GainSearchResult &result)
{
    m_result = result;
    m_table->setRowCount(int(result.candidates.size()));
    for (int i = 0; i < result.candidates.size(); ++i)
        fillRow(i, result.candidates.at(i));
    if (result.best) {
        for (int c = 0; c < kColumns; ++c) {
            QFont bold = m_table->item(*result.best, c)->font();
            bold.setBold(true);
            m_table->item(*result.best, c)->setFont(bold);
        }
    }
    m_compare->show(m_result);
    // The runner's typed outcome, worded here (its English message is for logs and lkctl).
    const QString text = GainSearchViewOutcome::text(result);
    setStatus(text, !result.ok());
    refresh();
    emit runningChanged(false);
}

std::optional<tuning::LoopGains> GainSearchView::best() const
{
    if (!m_result || !m_result->best)
        return std::nullopt;
    return m_result->candidates.at(*m_result->best).gains;
}

std::optional<QVector<qint64>> GainSearchView::suggestedValues(QString *why) const
{
    const auto refuse = [why](const QString &text) {
        *why = text;
        return std::nullopt;
    };
    const std::optional<tuning::LoopGains> gains = best();
    if (!gains || !m_result->read)
        return refuse(tr("Nothing was written: there is no suggestion yet."));
    if (!m_host->canSendToDrive() || m_host->driveId() != m_searchedId || !m_host->readComplete())
        return refuse(tr("Nothing was written: the suggestion is for drive %1, which is not "
                         "the drive selected and read on this connection.")
                          .arg(m_searchedId));
    const std::optional<ParamValues> held = ParamSetSpec::known(m_host->driveValues());
    const StepLoop searched = m_result->spec.loop;
    const QString prefix =
        searched == StepLoop::Position ? QStringLiteral("angle") : QStringLiteral("speed");
    const int kp = fieldIndex(m_host->spec(), prefix + QStringLiteral("_kp"));
    const int ki = fieldIndex(m_host->spec(), prefix + QStringLiteral("_ki"));
    if (!held || kp < 0 || ki < 0)
        return refuse(tr("Nothing was written: the drive's gains are not all known."));
    // Only the searched loop's Kp and Ki change, on the values the drive holds now.
    ParamValues values = *held;
    values[kp] = tuning::GainSearchStrategy::tuned(*gains, searched).kp;
    values[ki] = tuning::GainSearchStrategy::tuned(*gains, searched).ki;
    return values;
}

bool GainSearchView::writeBestToRam()
{
    QString why;
    const std::optional<ParamValues> values = suggestedValues(&why);
    if (!values || isRunning() || m_host->isBusy()) {
        setStatus(values ? tr("Nothing was written: wait until the drive is idle.") : why, true);
        return false;
    }
    m_host->table()->setPending(*values);
    m_host->writeToRam(); // the Tuning view's write: sent once, read back and compared
    m_ramWritten = true;
    setStatus(tr("The suggested gains went to the RAM of drive %1 (PID gains shows the "
                 "read-back). Try them with a step test or a sweep; Write to ROM keeps them.")
                  .arg(m_searchedId));
    refresh();
    return true;
}

bool GainSearchView::writeBestToRom()
{
    QString why;
    const std::optional<ParamValues> values = suggestedValues(&why);
    if (!values || !m_ramWritten || isRunning() || m_host->isBusy()) {
        setStatus(values ? tr("Nothing was written: write the suggestion to RAM first.") : why,
                  true);
        return false;
    }
    // What the drive holds must be the suggestion (read back after the RAM write).
    if (ParamSetSpec::known(m_host->driveValues()) != values) {
        setStatus(tr("Nothing was written: the drive does not hold the suggested gains in RAM "
                     "(read back). Write to RAM again first."),
                  true);
        return false;
    }
    m_host->table()->setPending(*values);
    m_host->writeToRom(); // asks first (the Tuning view's ROM confirmation); declining sends none
    setStatus(m_host->statusText());
    return true;
}

void GainSearchView::refresh()
{
    const bool running = isRunning();
    m_run->setText(running ? tr("Stop (Esc)") : tr("Search gains"));
    m_run->setToolTip(running ? tr("Stop at once: Motor Off, and the gains read back to RAM.")
                              : tr("Search the gains of the selected drive's loop (asks "
                                   "first)."));
    m_run->setEnabled(running || (m_host->canSendToDrive() && m_host->readComplete()));
    QString why;
    const bool suggestion = !running && suggestedValues(&why).has_value();
    m_writeRam->setEnabled(suggestion);
    m_writeRom->setEnabled(suggestion && m_ramWritten);
    for (QWidget *w : {static_cast<QWidget *>(m_overshoot), static_cast<QWidget *>(m_from),
                       static_cast<QWidget *>(m_to), static_cast<QWidget *>(m_maxCandidates),
                       static_cast<QWidget *>(m_measureBode), static_cast<QWidget *>(m_loop),
                       static_cast<QWidget *>(m_step)})
        w->setEnabled(!running);
    if (running)
        return;
    // The position loop only where an angle window is set (its steps stay inside it).
    const bool offered = TuningRunGate::positionOffered(*m_host);
    m_loop->setEnabled(offered);
    if (!offered && loop() == StepLoop::Position)
        m_loop->setCurrentIndex(m_loop->findData(int(StepLoop::Speed))); // refresh()es again
    const bool position = loop() == StepLoop::Position;
    m_form->setRowVisible(m_step, position);
    m_form->setRowVisible(m_speedSteps, !position);
    m_form->setRowVisible(m_measureBode, !position); // the Bode step is the speed loop's
    const std::optional<TuningRunDrive> drive =
        TuningRunGate::check(*m_host, gateLoop(loop()), nullptr);
    m_travel->setText(drive ? searchTravel(*drive, spec()) + bodeTimeText(*drive) : QString());
}

QString GainSearchView::bodeTimeText(const TuningRunDrive &drive) const
{
    if (!m_measureBode->isChecked() || loop() == StepLoop::Position)
        return {}; // the Bode step is the speed loop's
    const std::optional<double> seconds = spec().bodeSeconds(drive.series, drive.limits);
    return seconds ? QLatin1Char(' ') +
                         tr("The Bode of both adds about %1 s.").arg(Format::number(*seconds, 0))
                   : QLatin1Char(' ') + tr("The Bode of both is refused within these limits: "
                                           "clear the box or change the steps.");
}

void GainSearchView::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, StatusColors::current())
              : QString());
}

QString GainSearchView::statusText() const
{
    return m_status->text();
}

} // namespace lk::ui
