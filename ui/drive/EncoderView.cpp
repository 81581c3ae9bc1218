#include "EncoderView.h"

#include "ConfirmDialog.h"
#include "DriveSettingsStore.h"
#include "DriveText.h"
#include "EncoderLiveBox.h"
#include "EncoderResolutions.h"
#include "EncoderZeroTools.h"
#include "GenerationNote.h"
#include "RequestTracker.h"

#include <bus/BusSession.h>
#include <motor/ModelNameInfo.h>
#include <panels/StatusColors.h>
#include <protocol/Command.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QTime>

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

#include <cmath>

namespace lk::ui {

namespace {
using protocol::Command;
namespace build = protocol::build;
constexpr double kMaxGearRatio = 1000;
constexpr int kLogLines = 500;

QLabel *note(QWidget *parent)
{
    auto *l = new QLabel(parent);
    l->setWordWrap(true);
    return l;
}
} // namespace

const QList<int> &EncoderView::resolutions()
{
    return motor::EncoderResolution::choices();
}

EncoderView::EncoderView(QWidget *parent)
    : DriveView(parent), m_ownStore(std::make_unique<MemoryDriveStore>()),
      m_store(m_ownStore.get()), m_ownResolutions(std::make_unique<EncoderResolutions>()),
      m_resolutions(m_ownResolutions.get())
{
    setObjectName(QStringLiteral("encoder"));
    m_title = new QLabel(this);
    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.2);
    big.setBold(true);
    m_title->setFont(big);
    m_status = note(this);
    m_status->setObjectName(QStringLiteral("status"));

    auto *left = new QVBoxLayout;
    left->addWidget(m_title);
    m_live = new EncoderLiveBox(this);
    left->addWidget(m_live, 1);
    left->addWidget(buildSetupBox());
    auto *logBox = new QGroupBox(tr("What was done (this session)"), this);
    m_log = new QPlainTextEdit(logBox);
    m_log->setObjectName(QStringLiteral("log"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(kLogLines);
    m_log->setPlaceholderText(tr("Offset writes, angle clears and zero writes appear here."));
    auto *logLayout = new QVBoxLayout(logBox);
    logLayout->addWidget(m_log);
    auto *right = new QVBoxLayout;
    right->addWidget(buildOffsetBox());
    m_zero = new EncoderZeroTools(this);
    right->addWidget(m_zero);
    right->addWidget(m_status);
    right->addWidget(logBox, 1);
    auto *layout = new QHBoxLayout(this);
    layout->addLayout(left, 1);
    layout->addLayout(right, 1);

    connect(tracker(), &RequestTracker::pendingChanged, this, &EncoderView::refreshEnabled);
    wireZeroTools();
    setEncoderResolutions(nullptr);
    contextChanged(Change::Session | Change::Drive);
}

EncoderView::~EncoderView() = default; // m_extras gives the live reads back

const QVector<Command> &EncoderView::liveCommands()
{
    // 0x92 and 0x94 are in the dashboard's mix: the poll plan reads them once a round.
    static const QVector<Command> kCommands{Command::ReadEncoder, Command::ReadMultiTurn,
                                            Command::ReadSingleTurn};
    return kCommands;
}

QWidget *EncoderView::buildSetupBox()
{
    auto *box = new QGroupBox(tr("Encoder and gearbox"), this);
    m_bitsCombo = new QComboBox(box);
    m_bitsCombo->setObjectName(QStringLiteral("encoderBits"));
    for (int bits : resolutions())
        m_bitsCombo->addItem(tr("%1-bit").arg(bits), bits);
    m_bitsNote = note(box);
    m_ratioSpin = new QDoubleSpinBox(box);
    m_ratioSpin->setObjectName(QStringLiteral("gearRatio"));
    m_ratioSpin->setRange(1, kMaxGearRatio);
    m_ratioSpin->setDecimals(2);
    m_ratioSpin->setPrefix(QStringLiteral("1 : "));
    m_ratioSpin->setKeyboardTracking(false);
    m_ratioNote = note(box);
    connect(m_bitsCombo, &QComboBox::activated, this,
            [this] { setEncoderBits(m_bitsCombo->currentData().toInt()); });
    connect(m_ratioSpin, &QDoubleSpinBox::valueChanged, this, &EncoderView::setGearRatio);
    auto *form = new QFormLayout(box);
    form->addRow(tr("Resolution:"), m_bitsCombo);
    form->addRow(m_bitsNote);
    form->addRow(tr("Gear ratio:"), m_ratioSpin);
    form->addRow(m_ratioNote);
    return box;
}

QWidget *EncoderView::buildOffsetBox()
{
    auto *box = new QGroupBox(tr("Encoder offset (0x91)"), this);
    m_offsetSpin = new QSpinBox(box);
    m_offsetSpin->setObjectName(QStringLiteral("offsetInput"));
    m_useRaw = new QPushButton(tr("Use current raw"), box);
    m_useRaw->setObjectName(QStringLiteral("useRaw"));
    m_useRaw->setToolTip(tr("The present raw position becomes encoder 0"));
    m_writeOffset = new QPushButton(tr("Write offset\u2026"), box);
    m_writeOffset->setObjectName(QStringLiteral("writeOffset"));
    connect(m_useRaw, &QPushButton::clicked, this, [this] {
        if (m_encoder)
            m_offsetSpin->setValue(m_encoder->encoderRaw % countsPerTurn());
    });
    connect(m_writeOffset, &QPushButton::clicked, this,
            [this] { writeOffset(m_offsetSpin->value()); });
    auto *row = new QHBoxLayout;
    row->addWidget(m_offsetSpin, 1);
    row->addWidget(m_useRaw);
    row->addWidget(m_writeOffset);
    auto *layout = new QVBoxLayout(box);
    layout->addLayout(row);
    m_offsetNote = note(box);
    layout->addWidget(m_offsetNote);
    return box;
}

void EncoderView::wireZeroTools()
{
    m_zero->setSender(
        [this](const protocol::Request &request, RequestTracker::Callback done, int retries) {
            return tracker()->send(request, std::move(done), bus::Priority::Operator, retries);
        });
    connect(m_zero, &EncoderZeroTools::statusChanged, this, &EncoderView::setStatus);
    connect(m_zero, &EncoderZeroTools::busyChanged, this, &EncoderView::refreshEnabled);
    connect(m_zero, &EncoderZeroTools::multiTurnRead, this, [this](double deg) {
        m_multiTurnDeg = deg;
        refreshReadouts();
    });
    connect(m_zero, &EncoderZeroTools::angleCheckFinished, this, &EncoderView::angleCheckFinished);
    connect(m_zero, &EncoderZeroTools::zeroWriteFinished, this, &EncoderView::zeroWriteFinished);
    connect(m_zero, &EncoderZeroTools::turnCountCleared, this, &EncoderView::turnCountCleared);
}

void EncoderView::clearAngle()
{
    m_zero->clearAngle();
}

void EncoderView::writeZeroToRom()
{
    m_zero->writeZeroToRom();
}

void EncoderView::clearTurnCount()
{
    m_zero->clearTurnCount();
}

std::optional<AngleCheck> EncoderView::lastAngleCheck() const
{
    return m_zero->lastAngleCheck();
}

void EncoderView::setSettingsStore(DriveSettingsStore *store)
{
    m_store = store ? store : m_ownStore.get();
    if (m_resolutions == m_ownResolutions.get())
        m_ownResolutions->setSettingsStore(m_store);
    loadDriveSettings();
}

void EncoderView::setEncoderResolutions(EncoderResolutions *resolutions)
{
    if (m_resolutions)
        disconnect(m_resolutions, nullptr, this, nullptr);
    m_resolutions = resolutions ? resolutions : m_ownResolutions.get();
    const bool own = m_resolutions == m_ownResolutions.get();
    m_ownResolutions->setSession(own ? session() : nullptr); // a shared one is fed instead
    if (own)
        m_ownResolutions->setSettingsStore(m_store);
    connect(m_resolutions, &EncoderResolutions::changed, this, [this](int id) {
        if (id != driveId())
            return;
        const QSignalBlocker block(m_bitsCombo);
        m_bitsCombo->setCurrentIndex(m_bitsCombo->findData(encoderBits()));
        refreshReadouts();
    });
    loadDriveSettings();
}

int EncoderView::encoderBits() const
{
    return m_resolutions->of(driveId(), motor()).bits();
}

void EncoderView::loadDriveSettings()
{
    const QString name = motor().model ? motor().model->motorName : QString();
    const motor::ModelNameInfo info = motor::ModelNameInfo::parse(name);
    m_ratio = info.gearRatio;
    m_ratioSource = info.gearFromName ? tr("from the model name \"%1\"").arg(name)
                                      : tr("no gearbox in the model name");
    if (hasDrive()) {
        const QString key = DriveSettingsStore::driveKey(driveId(), motor());
        if (const auto ratio = m_store->gearRatio(key); ratio && *ratio != m_ratio) {
            m_ratio = *ratio;
            m_ratioSource = tr("your setting for this drive");
        }
    }
    const QSignalBlocker b1(m_bitsCombo), b2(m_ratioSpin);
    m_bitsCombo->setCurrentIndex(m_bitsCombo->findData(encoderBits()));
    m_ratioSpin->setValue(m_ratio);
    refreshReadouts();
}

int EncoderView::countsPerTurn() const
{
    return motor::encoderCountsPerTurn(encoderBits());
}

void EncoderView::setEncoderBits(int bits)
{
    if (!resolutions().contains(bits))
        return;
    if (hasDrive())
        m_resolutions->setUserBits(driveId(), motor(), bits);
    const QSignalBlocker block(m_bitsCombo);
    m_bitsCombo->setCurrentIndex(m_bitsCombo->findData(bits));
    refreshReadouts();
}

void EncoderView::setGearRatio(double ratio)
{
    if (!(ratio >= 1.0) || ratio > kMaxGearRatio)
        return;
    m_ratio = ratio;
    m_ratioSource = tr("your setting for this drive");
    if (hasDrive())
        m_store->setGearRatio(DriveSettingsStore::driveKey(driveId(), motor()), ratio);
    const QSignalBlocker block(m_ratioSpin);
    m_ratioSpin->setValue(ratio);
    refreshReadouts();
}

QString EncoderView::statusText() const
{
    return m_status->text();
}

void EncoderView::setStatus(const QString &text, bool error)
{
    if (!text.isEmpty() && text != m_status->text())
        m_log->appendPlainText(QStringLiteral("%1  %2  %3")
                                   .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")),
                                        driveTitle(), text));
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, palette(), true) : QString());
}

void EncoderView::contextChanged(Changes changes)
{
    if (changes & (Change::Session | Change::Drive)) {
        m_encoder.reset();
        m_multiTurnDeg.reset();
        m_singleTurnDeg.reset();
        m_busy = false;
        m_zero->abandon(true);
        setStatus(QString());
    }
    if (!tracker()->pendingCount()) {
        m_busy = false;
        m_zero->abandon(false);
    }
    if (changes & Change::Session) {
        disconnect(m_telemetry);
        if (session())
            m_telemetry = connect(session(), &bus::BusSession::telemetryReceived, this,
                                  &EncoderView::onTelemetry);
    }
    syncPollExtras();
    if ((changes & Change::Session) && m_resolutions == m_ownResolutions.get())
        m_ownResolutions->setSession(session());
    if (changes & (Change::Session | Change::Drive | Change::MotorInfo))
        loadDriveSettings();
    m_title->setText(driveTitle());
    if (!isConnected() && hasDrive())
        setStatus(cannotSendText(tr("Disconnected: the values shown are the last ones read.")));
    refreshReadouts();
    refreshEnabled();
}

void EncoderView::showEvent(QShowEvent *event)
{
    DriveView::showEvent(event);
    m_shown = true;
    syncPollExtras();
}

void EncoderView::hideEvent(QHideEvent *event)
{
    m_shown = false;
    syncPollExtras(); // live reads only while someone looks
    DriveView::hideEvent(event);
}

void EncoderView::syncPollExtras()
{
    if (m_shown && canSendToDrive())
        m_extras.hold(session(), driveId(), liveCommands());
    else
        m_extras.release();
}

void EncoderView::onTelemetry(const bus::TelemetryBatch &batch)
{
    if (!m_shown)
        return; // as the reads: only while someone looks
    // In arrival order, so the last value of a batch is the drive's latest. A batch that holds
    // a poll from before a sequence's own read-back holds that read-back's reply after it.
    bool changed = false;
    for (const bus::TelemetrySample &s : batch) {
        if (s.id != driveId() || !hasDrive())
            continue;
        if (s.encoderReading) {
            m_encoder = *s.encoderReading;
            m_resolutions->observe(driveId(), motor(), s.encoderReading->encoder);
            changed = true;
        }
        if (s.has(bus::TelemetryField::MultiTurn)) {
            m_multiTurnDeg = s.multiTurnDeg;
            changed = true;
        }
        if (s.has(bus::TelemetryField::SingleTurn)) {
            m_singleTurnDeg = s.singleTurnDeg;
            changed = true;
        }
    }
    if (!changed)
        return;
    refreshReadouts();
    if (!m_useRaw->isEnabled() && m_encoder)
        refreshEnabled(); // "Use current raw" needs a reading
}

quint64 EncoderView::readEncoder(bus::Priority priority)
{
    return tracker()->send(
        *build::plain(Command::ReadEncoder, driveId()).request,
        [this](const bus::RequestResult &r) {
            if (const auto *e = replyPayload<protocol::EncoderReading>(r)) {
                m_encoder = *e;
                m_resolutions->observe(driveId(), motor(), e->encoder);
                refreshReadouts();
            }
        },
        priority);
}

quint64 EncoderView::readMultiTurn(bus::Priority priority)
{
    return tracker()->send(
        *build::plain(Command::ReadMultiTurn, driveId()).request,
        [this](const bus::RequestResult &r) {
            if (const auto *a = replyPayload<protocol::MultiTurnAngle>(r)) {
                m_multiTurnDeg = a->degrees();
                refreshReadouts();
            }
        },
        priority);
}

void EncoderView::refreshReadouts()
{
    const motor::EncoderResolution resolution = m_resolutions->of(driveId(), motor());
    const int counts = resolution.countsPerTurn();
    m_live->setValues(m_encoder, m_multiTurnDeg, m_singleTurnDeg, resolution, m_ratio);
    const QString name = motor().model ? motor().model->motorName : QString();
    m_bitsNote->setText(tr("%1 counts per turn on the wire; %2.")
                            .arg(counts)
                            .arg(EncoderResolutions::sourceText(resolution, name, series())));
    m_ratioNote->setText(tr("Output shaft = rotor \u00f7 ratio; %1.").arg(m_ratioSource));
    m_offsetSpin->setRange(0, counts - 1);
}

void EncoderView::refreshEnabled()
{
    const bool can = canSendToDrive() && !m_busy && !m_zero->isBusy();
    // V2.35 has no 0x91 (docs/V2.35.md): its drives would not answer, so it is not offered.
    const QString noOffset = absenceOf(Command::WriteEncoderOffset);
    m_writeOffset->setEnabled(can && noOffset.isEmpty());
    m_offsetNote->setText(noOffset.isEmpty()
                              ? tr("The offset is the raw position that reads as encoder 0. The "
                                   "spec's command table calls 0x91 a ROM write: it may write the "
                                   "drive's flash.")
                              : noOffset);
    m_zero->setDrive(driveId(), motor(), canSendToDrive(), link());
    m_zero->setGearRatio(m_ratio);
    m_zero->setBlocked(m_busy);
    m_useRaw->setEnabled(hasDrive() && m_encoder.has_value());
    m_bitsCombo->setEnabled(hasDrive());
    m_ratioSpin->setEnabled(hasDrive());
    m_offsetSpin->setEnabled(hasDrive());
}

bool EncoderView::confirm(const ConfirmRequest &request)
{
    const int id = driveId();
    QString why;
    bool changed = false;
    // The dialog ran an event loop: the drive or the link may have changed meanwhile.
    if (ConfirmDialog::askUnchanged(
            this, request,
            [this, id] {
                return canSendToDrive() && driveId() == id && !m_busy && !m_zero->isBusy();
            },
            &why, &changed))
        return true;
    setStatus(why, changed);
    return false;
}

void EncoderView::writeOffset(int offset)
{
    if (!canSendToDrive() || m_busy || m_zero->isBusy())
        return;
    if (const QString absent = absenceOf(Command::WriteEncoderOffset); !absent.isEmpty()) {
        setStatus(absent, true);
        return;
    }
    const int counts = countsPerTurn();
    if (offset < 0 || offset >= counts) {
        setStatus(tr("Refused, nothing sent: the offset must be in 0..%1 for a %2-bit encoder.")
                      .arg(counts - 1)
                      .arg(encoderBits()),
                  true);
        return;
    }
    const protocol::BuildResult built = build::writeEncoderOffset(driveId(), offset);
    if (!built.ok()) {
        setStatus(DriveText::fieldError(built.error), true);
        return;
    }
    if (!confirm({QStringLiteral("write_encoder_offset"), tr("Write encoder offset"),
                  tr("Write encoder offset %1 to drive %2?").arg(offset).arg(driveId()),
                  tr("The zero of the encoder and of every angle moves, so position commands "
                     "go elsewhere afterwards. The spec's command table calls 0x91 a ROM write: "
                     "it may wear the drive's flash."),
                  tr("Write offset")}))
        return;
    m_busy = true;
    refreshEnabled();
    tracker()->send(
        *built.request,
        [this, offset](const bus::RequestResult &r) {
            if (!r.ok()) {
                m_busy = false;
                setStatus(DriveText::failure(r), true);
                refreshEnabled();
                emit offsetWriteFinished(false);
                return;
            }
            readBackOffset(offset);
        },
        bus::Priority::Operator, 0);
}

void EncoderView::readBackOffset(int offset)
{
    // Show what the drive applied, not what was asked.
    tracker()->send(*build::plain(Command::ReadEncoder, driveId()).request,
                    [this, offset](const bus::RequestResult &back) {
                        m_busy = false;
                        const auto *e = replyPayload<protocol::EncoderReading>(back);
                        const bool ok = e && e->encoderOffset == offset;
                        if (e) {
                            m_encoder = *e;
                            m_resolutions->observe(driveId(), motor(), e->encoder);
                        }
                        setStatus(ok  ? tr("Encoder offset %1 written and read back.").arg(offset)
                                  : e ? tr("Wrote offset %1, but the drive reports %2.")
                                            .arg(offset)
                                            .arg(e->encoderOffset)
                                      : DriveText::failure(back),
                                  !ok);
                        refreshReadouts();
                        refreshEnabled();
                        emit offsetWriteFinished(ok);
                    });
}

QString EncoderView::absenceOf(Command command) const
{
    if (!hasDrive())
        return QString();
    if (command == Command::ClearTurnCount)
        return m_zero->turnCountAbsence();
    return GenerationNote::absence(motor(), command, tr("encoder offset"), link());
}

} // namespace lk::ui
