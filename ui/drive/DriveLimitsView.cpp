#include "DriveLimitsView.h"

#include "ParamExchange.h"
#include "ParameterTable.h"
#include "RequestTracker.h"

#include <panels/StatusColors.h>

#include <QtCore/QTime>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

DriveLimitsView::DriveLimitsView(QWidget *parent) : DriveView(parent)
{
    setObjectName(QStringLiteral("driveLimits"));
    m_exchange = new ParamExchange(tracker(), this);
    m_exchange->setSpec(m_spec);

    const ParamSetTexts texts = m_spec->texts();
    auto *explain = new QLabel(texts.note, this);
    explain->setWordWrap(true);
    m_unsupported = new QLabel(this);
    m_unsupported->setObjectName(QStringLiteral("unsupported"));
    m_unsupported->setWordWrap(true);
    m_unsupported->setText(tr("This drive speaks protocol V2.3: these settings do not exist in its "
                              "protocol generation (they came with V2.35, ParamIDs 0x99..0x9E)."));

    m_editor = new QWidget(this);
    m_table = new ParameterTable(m_editor);
    m_table->setFields(m_spec->fields());
    auto make = [this](const char *name, const QString &text, const QString &tip) {
        auto *b = new QPushButton(text, m_editor);
        b->setObjectName(QLatin1String(name));
        b->setToolTip(tip);
        return b;
    };
    m_read = make("limitsRead", tr("Read limits"), texts.readTip);
    m_writeRam = make("limitsWriteRam", tr("Write limits to RAM"), texts.ramTip);
    m_writeRom = make("limitsWriteRom", tr("Write limits to ROM\u2026"), texts.romTip);
    connect(m_read, &QPushButton::clicked, this, &DriveLimitsView::readFromDrive);
    connect(m_writeRam, &QPushButton::clicked, this, &DriveLimitsView::writeToRam);
    connect(m_writeRom, &QPushButton::clicked, this, &DriveLimitsView::writeToRom);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_read);
    buttons->addWidget(m_writeRam);
    buttons->addWidget(m_writeRom);
    auto *editorLayout = new QVBoxLayout(m_editor);
    editorLayout->setContentsMargins(0, 0, 0, 0);
    editorLayout->addWidget(m_table);
    editorLayout->addLayout(buttons);

    m_mismatch = new QLabel(this);
    m_mismatch->setObjectName(QStringLiteral("limitsMismatch"));
    m_mismatch->setWordWrap(true);
    m_mismatch->setStyleSheet(
        StatusColors::boxStyle(StatusColors::Role::Error, StatusColors::current()));
    m_mismatch->hide();
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("limitsStatus"));
    m_status->setWordWrap(true);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(explain);
    layout->addWidget(m_unsupported);
    layout->addWidget(m_editor);
    layout->addWidget(m_mismatch);
    layout->addWidget(m_status);
    layout->addStretch();

    connect(m_exchange, &ParamExchange::readFinished, this, &DriveLimitsView::onReadDone);
    connect(tracker(), &RequestTracker::pendingChanged, this, &DriveLimitsView::refreshEnabled);
    connect(m_table, &ParameterTable::edited, this, &DriveLimitsView::refreshEnabled);
    contextChanged(Change::Session | Change::Drive);
}

DriveLimitsView::~DriveLimitsView() = default;

bool DriveLimitsView::isSupported() const
{
    return hasDrive() && motor().generation == protocol::Generation::V2_35;
}

HeldValues DriveLimitsView::driveValues() const
{
    return m_exchange->held();
}

QString DriveLimitsView::statusText() const
{
    return m_status->text();
}

QString DriveLimitsView::mismatchText() const
{
    return m_mismatch->isHidden() ? QString() : m_mismatch->text();
}

bool DriveLimitsView::isBusy() const
{
    return tracker()->pendingCount() > 0;
}

void DriveLimitsView::contextChanged(Changes changes)
{
    if (tracker()->pendingCount() == 0)
        m_exchange->forgetOutstanding();
    const DriveLimitSet *spec =
        series() == protocol::Series::MS ? &m_powerLimits : &m_currentLimits;
    // Another set (series or generation learned late) is another drive as far as values go.
    const bool otherSet = spec != m_spec || isSupported() != m_shownSupported;
    const bool reset =
        otherSet || (changes & (Change::Session | Change::Drive | Change::Connection));
    if (spec != m_spec) {
        m_spec = spec;
        m_exchange->setSpec(spec);
        m_table->setFields(spec->fields());
    }
    m_shownSupported = isSupported();
    if (reset) {
        m_readComplete = false; // what was read belongs to one drive on one connection
        m_exchange->clear();
        m_table->setHolds(m_exchange->held());
        m_firstRead.reset();
        m_table->setOriginal(std::nullopt);
        m_table->clearPending();
        m_mismatch->hide();
        setStatus(QString());
    }
    m_unsupported->setVisible(hasDrive() && !isSupported());
    m_editor->setVisible(!hasDrive() || isSupported());
    if (reset && isSupported() && canSendToDrive())
        readFromDrive();
    refreshEnabled();
}

void DriveLimitsView::readFromDrive()
{
    if (!isSupported() || !canSendToDrive() || isBusy())
        return;
    m_takePending = !m_table->pending() || !m_table->anyChanged();
    setStatus(QString());
    m_exchange->read(driveId());
}

void DriveLimitsView::onReadDone(int id)
{
    if (id != driveId())
        return;
    m_readComplete = m_exchange->complete();
    const HeldValues held = m_exchange->held();
    m_table->setHolds(held);
    if (m_readComplete && !m_firstRead) {
        m_firstRead = ParamSetSpec::known(held);
        m_table->setOriginal(m_firstRead);
    }
    if (m_readComplete && (m_takePending || !m_table->pending()))
        m_table->setPending(*ParamSetSpec::known(held));
    else if (!m_readComplete)
        m_table->clearPending(); // never edit against values that are not known
    m_takePending = false;
    if (const std::optional<SentValues> sent = m_exchange->takeSent()) {
        const QStringList problems = m_spec->readBackProblems(*sent, held);
        m_mismatch->setText(problems.join(QLatin1Char('\n')));
        m_mismatch->setVisible(!problems.isEmpty());
        const QStringList failures = m_exchange->writeFailures();
        if (!failures.isEmpty())
            setStatus(tr("The write failed: %1").arg(failures.join(QLatin1Char(' '))), true);
        else if (!problems.isEmpty())
            setStatus(tr("Written, but the read-back differs (below)."), true);
        else
            setStatus(m_spec->written(*sent, id));
    } else if (!m_readComplete) {
        setStatus(tr("Could not read the limits of drive %1: %2 Editing and writing stay off "
                     "until every limit has been read.")
                      .arg(id)
                      .arg(m_exchange->readFailure()),
                  true);
    } else {
        setStatus(tr("Limits read from drive %1 at %2.")
                      .arg(id)
                      .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))));
    }
    refreshEnabled();
    emit parametersRead(id);
}

void DriveLimitsView::writeToRam()
{
    write(false);
}

void DriveLimitsView::writeToRom()
{
    write(true);
}

void DriveLimitsView::write(bool rom)
{
    if (!isSupported() || !canSendToDrive() || isBusy())
        return;
    const std::optional<ParamValues> values = m_table->pending();
    if (!m_readComplete || !values) {
        setStatus(tr("Nothing was sent: the drive's limits have not all been read on this "
                     "connection. Read limits first."),
                  true);
        return;
    }
    const int id = driveId();
    if (rom && !ConfirmDialog::ask(this, m_spec->romQuestion(id, *values))) {
        setStatus(tr("ROM write cancelled: nothing was sent."));
        return;
    }
    // The dialog ran an event loop: the drive, the link or the read may have changed meanwhile.
    if (!canSendToDrive() || driveId() != id || isBusy() || !m_readComplete) {
        setStatus(tr("The drive or the connection changed: nothing was sent."), true);
        return;
    }
    m_takePending = false;
    const QString error = m_exchange->write(id, *values, rom);
    if (!error.isEmpty()) {
        setStatus(tr("Nothing was sent: %1").arg(error), true);
        return;
    }
    m_mismatch->hide();
    setStatus(rom ? tr("Writing limits to the ROM of drive %1\u2026").arg(id)
                  : tr("Writing limits to the RAM of drive %1\u2026").arg(id));
    refreshEnabled();
}

void DriveLimitsView::refreshEnabled()
{
    const bool idle = !isBusy();
    const bool read = isSupported() && canSendToDrive() && m_readComplete;
    const bool pending = m_table->pending().has_value();
    m_read->setEnabled(isSupported() && canSendToDrive() && idle);
    m_writeRam->setEnabled(read && idle && pending);
    m_writeRom->setEnabled(read && idle && pending);
    m_table->setEditable(read);
}

void DriveLimitsView::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? StatusColors::textStyle(StatusColors::Role::Error, palette())
                                  : QString());
}

} // namespace lk::ui
