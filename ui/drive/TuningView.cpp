#include "TuningView.h"

#include "DriveLimitsView.h"
#include "DriveText.h"
#include "FrequencyTuningView.h"
#include "LoopPlot.h"
#include "ParameterTable.h"
#include "RequestTracker.h"
#include "TuningFile.h"
#include "TuningSetCycle.h"
#include "TuningText.h"

#include <bus/BusSession.h>
#include <motor/ModelNameInfo.h>
#include <panels/FileDialogs.h>
#include <panels/StatusColors.h>
#include <plot/SampleRing.h>
#include <record/ParameterSet.h>
#include <tuning/StepRunList.h>
#include <tuning/StepRunsView.h>
#include <tuning/StepTestPanel.h>

#include <QtCore/QDateTime>
#include <QtCore/QTime>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QVBoxLayout>

#include <cmath>

namespace lk::ui {

namespace {
constexpr int kLeftColumnWidth = 470;

QLabel *banner(const QString &name, const QString &style, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setStyleSheet(style);
    label->hide();
    return label;
}
} // namespace

TuningView::TuningView(QWidget *parent) : DriveView(parent)
{
    setObjectName(QStringLiteral("tuning"));
    buildUi();
    m_cycle = new TuningSetCycle(this, tracker(), m_table);
    m_cycle->setSpec(m_spec);
    wireCycle();
    connect(tracker(), &RequestTracker::pendingChanged, this, &TuningView::refreshEnabled);
    connect(m_table, &ParameterTable::loopFocused, m_plot, &LoopPlot::setLoop);
    connect(m_table, &ParameterTable::edited, this, &TuningView::refreshEnabled);
    contextChanged(Change::Session | Change::Drive);
}

TuningView::~TuningView() = default;

void TuningView::wireCycle()
{
    connect(m_cycle, &TuningSetCycle::statusChanged, this, [this](const QString &text, bool error) {
        m_status->setText(text);
        m_status->setStyleSheet(
            error ? StatusColors::textStyle(StatusColors::Role::Error, palette()) : QString());
    });
    connect(m_cycle, &TuningSetCycle::mismatchChanged, this, [this](const QString &text) {
        if (text.isEmpty()) {
            m_mismatch->hide();
            return;
        }
        m_mismatch->setText(text);
        m_mismatch->show();
    });
    connect(m_cycle, &TuningSetCycle::writeAcknowledged, this, [this](bool rom) {
        m_plot->markChange(rom ? tr("ROM write") : tr("RAM write")); // the moment on the trace
    });
    connect(m_cycle, &TuningSetCycle::readFinished, this, [this](int id) {
        refreshWarnings();
        refreshEnabled();
        emit parametersRead(id);
    });
    connect(m_cycle, &TuningSetCycle::stateChanged, this, &TuningView::refreshEnabled);
}

void TuningView::buildUi()
{
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("driveTitle"));
    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.2);
    big.setBold(true);
    m_title->setFont(big);

    m_box = new QGroupBox(this);
    m_table = new ParameterTable(m_box);
    m_note = new QLabel(m_box);
    m_note->setObjectName(QStringLiteral("generationNote"));
    m_note->setWordWrap(true);
    m_ramOnlyNote = new QLabel(TuningText::can236RamOnly(), m_box);
    m_ramOnlyNote->setObjectName(QStringLiteral("ramOnlyNote"));
    m_ramOnlyNote->setWordWrap(true);
    m_ramOnlyNote->setVisible(false);
    auto *boxLayout = new QVBoxLayout(m_box);
    boxLayout->addWidget(m_table);
    boxLayout->addWidget(m_note);
    boxLayout->addWidget(m_ramOnlyNote);

    m_romWarning = banner(QStringLiteral("romWarning"), QString(), this);
    m_mismatch =
        banner(QStringLiteral("mismatch"),
               StatusColors::boxStyle(StatusColors::Role::Error, StatusColors::current()), this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);

    auto *gains = new QWidget(this);
    auto *gainsLayout = new QVBoxLayout(gains);
    gainsLayout->addWidget(m_box);
    gainsLayout->addWidget(buildButtons());
    gainsLayout->addWidget(m_romWarning);
    gainsLayout->addWidget(m_mismatch);
    gainsLayout->addWidget(m_status);
    gainsLayout->addStretch();
    // The drive's own limits sit beside the gains: the same read / write / read-back cycle,
    // but settings of the drive, not of a loop.
    m_limits = new DriveLimitsView(this);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("tuningTabs"));
    m_tabs->addTab(gains, tr("PID gains"));
    m_tabs->addTab(m_limits, tr("Drive limits"));

    auto *left = new QVBoxLayout;
    left->addWidget(m_title);
    left->addWidget(m_tabs, 1);
    auto *leftWidget = new QWidget(this);
    leftWidget->setLayout(left);
    leftWidget->setFixedWidth(kLeftColumnWidth);

    // Beside the table: the live loop, or the step tests and their runs compared.
    m_plot = new LoopPlot(this);
    m_side = new QTabWidget(this);
    m_side->setObjectName(QStringLiteral("tuningSide"));
    m_side->addTab(m_plot, tr("Live plot"));
    m_side->addTab(buildStepTab(), tr("Step response"));
    m_frequency = new FrequencyTuningView(this);
    m_side->addTab(m_frequency, tr("Frequency response"));
    connect(m_frequency, &FrequencyTuningView::runningChanged, this, &TuningView::refreshEnabled);
    auto *layout = new QHBoxLayout(this);
    layout->addWidget(leftWidget);
    layout->addWidget(m_side, 1);
}

QWidget *TuningView::buildStepTab()
{
    m_runs = new StepRunList(this);
    m_stepTest = new StepTestPanel(m_runs, this);
    m_stepRuns = new StepRunsView(m_runs, this);
    auto *tab = new QWidget(this);
    auto *layout = new QVBoxLayout(tab);
    layout->addWidget(m_stepTest);
    layout->addWidget(m_stepRuns, 1);
    StepTestSources sources;
    sources.gains = [this] { return heldObject(false); };
    sources.ramps = [this] { return heldObject(true); };
    sources.effortLimit = [this] { return tuning::seriesEffortLimit(series()); };
    sources.angleDeg = [this]() -> std::optional<double> {
        const SampleRing *ring = m_plot->store()->ring(driveId(), TelemetryChannel::MultiTurn);
        if (!ring || ring->isEmpty())
            return std::nullopt;
        return ring->valueAt(ring->size() - 1);
    };
    m_stepTest->setSources(sources);
    connect(m_stepTest, &StepTestPanel::emergencyStopRequested, this,
            &TuningView::emergencyStopRequested);
    connect(m_stepTest, &StepTestPanel::runningChanged, this, &TuningView::refreshEnabled);
    connect(m_stepTest, &StepTestPanel::runFinished, this, [this] { showStepResponse(true); });
    return tab;
}

void TuningView::setStepTestLimits(
    std::function<std::optional<safety::SoftLimits>(QString *why)> limits)
{
    StepTestSources sources = m_stepTest->sources();
    sources.limits = std::move(limits);
    m_stepTest->setSources(sources);
}

void TuningView::showStepResponse(bool show)
{
    m_side->setCurrentIndex(show ? 1 : 0);
}

void TuningView::haltLocalMotion(const QString &reason)
{
    m_stepTest->halt(reason);
    m_frequency->halt();
}

QJsonObject TuningView::heldObject(bool ramps) const
{
    // Only values a complete read gave: a gain that was not read is absent, never 0.
    QJsonObject out;
    if (!m_cycle->readComplete())
        return out;
    const QStringList keys = ramps ? tuning::stepRunRampKeys() : tuning::stepRunGainKeys();
    const QVector<ParamField> fields = m_spec->fields();
    const HeldValues held = m_cycle->held();
    for (int i = 0; i < fields.size() && i < held.size(); ++i) {
        if (held.at(i) && keys.contains(fields.at(i).key))
            out.insert(fields.at(i).key,
                       double(*held.at(i)) / std::pow(10.0, fields.at(i).decimals));
    }
    return out;
}

void TuningView::updateStepDrive()
{
    StepTestDrive d;
    d.session = session();
    d.id = driveId();
    d.canSend = canSendToDrive();
    d.series = series();
    if (const auto &m = motor().model) {
        d.model = m->motorName;
        d.generation = protocol::generationName(m->generation);
        d.gearRatio = motor::ModelNameInfo::parse(m->motorName).gearRatio;
    }
    m_stepTest->setDrive(d);
}

QWidget *TuningView::buildButtons()
{
    auto make = [this](const QString &name, const QString &text, const QString &tip) {
        auto *b = new QPushButton(text, this);
        b->setObjectName(name);
        b->setToolTip(tip);
        return b;
    };
    m_read = make(QStringLiteral("read"), tr("Read from drive"), QString());
    m_writeRam = make(QStringLiteral("writeRam"), tr("Write to RAM"), QString());
    m_writeRom = make(QStringLiteral("writeRom"), tr("Write to ROM\u2026"), QString());
    m_undo = make(QStringLiteral("undo"), QString(), QString()); // named by refreshEnabled()
    m_save = make(QStringLiteral("save"), tr("Save to file\u2026"),
                  tr("Save what the drive holds, with model, firmware and time, as JSON."));
    m_load = make(QStringLiteral("load"), tr("Load from file\u2026"),
                  tr("Load a parameter file into the pending edit; nothing is written. Needs a "
                     "complete read of the drive first."));
    connect(m_read, &QPushButton::clicked, this, &TuningView::readFromDrive);
    connect(m_writeRam, &QPushButton::clicked, this, &TuningView::writeToRam);
    connect(m_writeRom, &QPushButton::clicked, this, &TuningView::writeToRom);
    connect(m_undo, &QPushButton::clicked, this, &TuningView::restoreFirstRead);
    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString what =
            (motor().model ? motor().model->motorName + QLatin1Char('-') : QString()) +
            QStringLiteral("parameters");
        const QString path = FileDialogs::saveFile(
            this, FileDialogs::Purpose::Parameters, tr("Save drive parameters"),
            FileDialogs::suggestedName(what, {driveId()}, QDateTime::currentDateTime(),
                                       QStringLiteral("json")),
            tr("Parameter files (*.json)"));
        if (!path.isEmpty())
            saveParameters(path);
    });
    connect(m_load, &QPushButton::clicked, this, [this] {
        const QString path =
            FileDialogs::openFile(this, FileDialogs::Purpose::Parameters,
                                  tr("Load drive parameters"), tr("Parameter files (*.json)"));
        if (!path.isEmpty())
            loadParameters(path);
    });
    auto *w = new QWidget(this);
    auto *grid = new QGridLayout(w);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(m_read, 0, 0);
    grid->addWidget(m_writeRam, 0, 1);
    grid->addWidget(m_writeRom, 0, 2);
    grid->addWidget(m_undo, 1, 0, 1, 3); // its name carries a time: the whole row
    grid->addWidget(m_save, 2, 0);
    grid->addWidget(m_load, 2, 1);
    // The write-test-compare loop: write to RAM, then one click repeats the last step test.
    m_repeatStep = make(QStringLiteral("repeatStepTest"), tr("Repeat step test"),
                        tr("Run the last step test again with the gains the drive holds now, "
                           "and compare it with the runs before (Step response tab)."));
    connect(m_repeatStep, &QPushButton::clicked, this, [this] {
        showStepResponse(true);
        m_stepTest->repeatLast();
    });
    grid->addWidget(m_repeatStep, 2, 2);
    return w;
}

void TuningView::setTelemetryStore(TelemetryStore *store)
{
    m_plot->setStore(store);
}

HeldValues TuningView::driveValues() const
{
    return m_cycle->held();
}

bool TuningView::readComplete() const
{
    return m_cycle->readComplete();
}

void TuningView::readFromDrive()
{
    m_cycle->readFromDrive();
}

void TuningView::writeToRam()
{
    m_cycle->write(TuningSetCycle::WriteKind::Ram);
}

void TuningView::writeToRom()
{
    if (m_ramOnly) { // no button, and no way around it: a V2.36 CAN drive has no ROM write
        setStatus(TuningText::can236RamOnly(), true);
        return;
    }
    m_cycle->write(TuningSetCycle::WriteKind::Rom);
}

void TuningView::setLink(protocol::Link link)
{
    if (m_link == link)
        return;
    m_link = link;
    contextChanged(Change::MotorInfo);
}

bool TuningView::updateRamOnly()
{
    const bool ramOnly = m_link == protocol::Link::Can && hasDrive() &&
                         motor().generation == protocol::Generation::V2_35;
    if (ramOnly == m_ramOnly)
        return false;
    m_ramOnly = ramOnly;
    return true;
}

void TuningView::restoreFirstRead()
{
    m_cycle->write(TuningSetCycle::WriteKind::RestoreFirstRead);
}

const ParamSetSpec *TuningView::specFor(protocol::Generation generation) const
{
    if (m_ramOnly) // CAN V2.36: the control parameters, 0xC0/0xC1
        return &m_can236;
    if (generation == protocol::Generation::V2_35)
        return &m_v235;
    return &m_v23;
}

void TuningView::selectSpec()
{
    const ParamSetSpec *spec = specFor(motor().generation);
    if (spec != m_spec || m_table->rowCount() == 0) {
        m_spec = spec;
        m_cycle->setSpec(spec);
        m_table->setFields(spec->fields());
    }
    const ParamSetTexts texts = spec->texts();
    m_box->setTitle(texts.title);
    m_note->setText(texts.note);
    m_read->setToolTip(texts.readTip);
    m_writeRam->setToolTip(texts.ramTip);
    m_writeRom->setToolTip(texts.romTip);
}

bool TuningView::romWarningShown() const
{
    return m_romWarningActive;
}

QString TuningView::mismatchText() const
{
    return m_mismatch->isHidden() ? QString() : m_mismatch->text();
}

QString TuningView::statusText() const
{
    return m_status->text();
}

bool TuningView::isBusy() const
{
    return m_cycle->isBusy();
}

void TuningView::contextChanged(Changes changes)
{
    const bool linkUp = (changes & Change::Connection) && isConnected();
    const bool linkDown = (changes & Change::Connection) && !isConnected();
    // The generation learned late (MotorInfo) changes the set: values of the other set are void.
    const bool ramOnlyChanged = updateRamOnly(); // always: never skipped by the test before
    if (specFor(motor().generation) != m_spec || ramOnlyChanged)
        changes |= Change::Drive;
    if (changes & Change::Session) {
        disconnect(m_telemetry);
        if (session())
            m_telemetry = connect(session(), &bus::BusSession::telemetryReceived, m_plot,
                                  &LoopPlot::appendTelemetry);
    }
    m_cycle->contextChanged(changes);
    if (changes & (Change::Session | Change::Drive) || linkUp) {
        selectSpec();
        m_cycle->startOver();
    }
    m_cycle->showDrive();
    m_plot->setDrive(driveId(), series() == protocol::Series::MS);
    m_title->setText(driveTitle());
    if (canSendToDrive() && (changes & (Change::Session | Change::Drive | Change::Connection)))
        m_cycle->read(true);
    if (linkDown && hasDrive())
        setStatus(cannotSendText(tr("Disconnected: the values shown are the last ones read. Tuning "
                                    "resumes after the drive has been read again on the next "
                                    "connection.")));
    forwardContext(changes); // after the gains' read: those go on the bus first
    updateStepDrive();
    refreshWarnings();
    refreshEnabled();
}

void TuningView::forwardContext(Changes changes)
{
    if (changes & Change::Session)
        m_limits->setSession(session());
    if (changes & Change::Connection)
        m_limits->setConnected(isConnected(), cannotSendText(QString()));
    if (changes & (Change::Session | Change::Drive | Change::MotorInfo)) {
        // A V2.36 CAN drive's limits are 0xC0 IDs, not V2.35's 0x40 ParamIDs: not read there.
        if (hasDrive() && !m_ramOnly)
            m_limits->setDrive(driveId(), motor());
        else
            m_limits->clearDrive();
    }
}

void TuningView::refreshWarnings()
{
    const TuningSetCycle::RamRomNote note = m_cycle->ramRomNote();
    m_romWarningActive = note.warning;
    m_romWarning->setText(tr("RAM and ROM: %1").arg(note.text));
    const QPalette pal = StatusColors::current();
    m_romWarning->setStyleSheet(m_romWarningActive
                                    ? StatusColors::boxStyle(StatusColors::Role::Warning, pal)
                                    : StatusColors::boxStyle(StatusColors::Role::Info, pal));
    m_romWarning->setVisible(hasDrive() && !m_ramOnly); // RAM only: the note says it
}

void TuningView::refreshEnabled()
{
    // No gain writes while a step test, a sweep or a search runs: a trace would mix two sets
    // of gains, and the sweep or search puts the gains it read back at its end. One of the
    // three moves the drive at a time (each replaces the other's setpoint stream).
    const bool frequencyRunning = m_frequency->isRunning();
    const bool idle = !isBusy() && !m_stepTest->isRunning() && !frequencyRunning;
    m_stepTest->setEnabled(!frequencyRunning);
    m_frequency->setEnabled(!m_stepTest->isRunning());
    const bool read = canSendToDrive() && m_cycle->readComplete();
    const bool pending = m_table->pending().has_value();
    m_read->setEnabled(canSendToDrive() && idle);
    m_writeRam->setEnabled(read && idle && pending);
    m_writeRom->setEnabled(read && idle && pending && !m_ramOnly);
    m_writeRom->setVisible(!m_ramOnly); // absent, not greyed: the drive has no ROM write
    m_ramOnlyNote->setVisible(m_ramOnly);
    m_tabs->setTabEnabled(m_tabs->indexOf(m_limits), !m_ramOnly);
    m_undo->setEnabled(read && idle && m_cycle->firstReadAt().has_value());
    record::ParameterSet probe;
    m_save->setEnabled(hasDrive() && m_spec->toFile(m_cycle->held(), probe));
    m_load->setEnabled(read && idle);
    m_table->setEditable(read);
    m_repeatStep->setEnabled(m_stepTest->canRepeat() && idle);
    refreshRestoreButton();
}

void TuningView::refreshRestoreButton()
{
    if (const std::optional<QTime> firstRead = m_cycle->firstReadAt()) {
        const QString at = TuningText::time(*firstRead);
        m_undo->setText(tr("Restore values read at %1\u2026").arg(at));
        m_undo->setToolTip(tr("Write the values first read from this drive at %1 back to its "
                              "RAM (asks first), then read back.")
                               .arg(at));
    } else {
        m_undo->setText(tr("Restore values first read\u2026"));
        m_undo->setToolTip(tr("Writes the values of the first complete read of this drive on "
                              "this connection back to its RAM (asks first)."));
    }
}

void TuningView::setStatus(const QString &text, bool error)
{
    m_cycle->setStatus(text, error);
}

QString TuningView::saveParameters(const QString &path)
{
    const TuningFileResult r =
        TuningFile::save(path, *m_spec, m_cycle->held(), driveId(), motor(), series());
    setStatus(r.status, !r.error.isEmpty());
    return r.error;
}

QString TuningView::loadParameters(const QString &path)
{
    if (!canSendToDrive() || !m_cycle->readComplete() || isBusy()) {
        const QString error = tr("Nothing was loaded: a file is loaded against the drive's "
                                 "values, so read the drive's values first.");
        setStatus(error, true);
        return error;
    }
    const TuningFileResult r = TuningFile::load(
        path, *m_spec, m_table->pending().value_or(*ParamSetSpec::known(m_cycle->held())), motor());
    if (r.values)
        m_table->setPending(*r.values);
    setStatus(r.status, !r.error.isEmpty());
    refreshEnabled();
    return r.error;
}

void TuningView::changeEvent(QEvent *event)
{
    DriveView::changeEvent(event);
    // The palette (light/dark) changed while running. The sheets are set on children, so
    // this does not loop.
    if (event->type() != QEvent::PaletteChange)
        return;
    m_mismatch->setStyleSheet(
        StatusColors::boxStyle(StatusColors::Role::Error, StatusColors::current()));
    refreshWarnings();
}

} // namespace lk::ui
