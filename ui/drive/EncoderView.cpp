#include "EncoderView.h"

#include "ConfirmDialog.h"
#include "DriveSettingsStore.h"
#include "DriveText.h"
#include "EncoderLiveBox.h"
#include "EncoderResolutions.h"
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

template <typename T> const T *payload(const bus::RequestResult &r)
{
    return r.ok() && r.reply ? std::get_if<T>(&r.reply->payload) : nullptr;
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
    right->addWidget(buildZeroBox());
    right->addWidget(m_status);
    right->addWidget(logBox, 1);
    auto *layout = new QHBoxLayout(this);
    layout->addLayout(left, 1);
    layout->addLayout(right, 1);

    connect(tracker(), &RequestTracker::pendingChanged, this, &EncoderView::refreshEnabled);
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

QWidget *EncoderView::buildZeroBox()
{
    auto *box = new QGroupBox(tr("Zero"), this);
    m_clearAngle = new QPushButton(tr("Clear motor angle (0x95)\u2026"), box);
    m_clearAngle->setObjectName(QStringLiteral("clearAngle"));
    m_zeroRom = new QPushButton(tr("Write current position to ROM as zero (0x19)\u2026"), box);
    m_zeroRom->setObjectName(QStringLiteral("zeroRom"));
    connect(m_clearAngle, &QPushButton::clicked, this, &EncoderView::clearAngle);
    connect(m_zeroRom, &QPushButton::clicked, this, &EncoderView::writeZeroToRom);
    auto *clearText = note(box);
    clearText->setText(tr("Multi-turn and single-turn angle become 0 here until power-off; the "
                          "result is checked with read_multi_turn (0x92)."));
    auto *zeroText = note(box);
    zeroText->setText(tr("Stores the present encoder position as the zero in flash. Takes "
                         "effect only after a power cycle; each write wears the flash."));
    m_clearTurns = new QPushButton(tr("Clear turn count (0x93)\u2026"), box);
    m_clearTurns->setObjectName(QStringLiteral("clearTurns"));
    connect(m_clearTurns, &QPushButton::clicked, this, &EncoderView::clearTurnCount);
    m_clearTurnsNote = note(box);
    m_clearTurnsNote->setObjectName(QStringLiteral("clearTurnsNote"));
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(m_clearAngle);
    layout->addWidget(clearText);
    layout->addWidget(m_clearTurns);
    layout->addWidget(m_clearTurnsNote);
    layout->addWidget(m_zeroRom);
    layout->addWidget(zeroText);
    return box;
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
        m_angleCheck.reset();
        m_busy = false;
        setStatus(QString());
    }
    if (!tracker()->pendingCount())
        m_busy = false;
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
        setStatus(tr("Disconnected: the values shown are the last ones read."));
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
    if (m_shown && canSend())
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

void EncoderView::refreshNow()
{
    if (!canSend())
        return;
    readEncoder(bus::Priority::Operator);
    readMultiTurn(bus::Priority::Operator);
}

quint64 EncoderView::readEncoder(bus::Priority priority)
{
    return tracker()->send(
        *build::plain(Command::ReadEncoder, driveId()).request,
        [this](const bus::RequestResult &r) {
            if (const auto *e = payload<protocol::EncoderReading>(r)) {
                m_encoder = *e;
                m_resolutions->observe(driveId(), motor(), e->encoder);
                refreshReadouts();
            }
        },
        priority);
}

quint64 EncoderView::readMultiTurn(bus::Priority priority, std::function<void(double)> then)
{
    return tracker()->send(
        *build::plain(Command::ReadMultiTurn, driveId()).request,
        [this, then](const bus::RequestResult &r) {
            const auto *a = payload<protocol::MultiTurnAngle>(r);
            if (a) {
                m_multiTurnDeg = a->degrees();
                refreshReadouts();
            }
            if (then) {
                if (a)
                    then(a->degrees());
                else {
                    m_busy = false;
                    setStatus(DriveText::failure(r), true);
                    refreshEnabled();
                }
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
    const bool can = canSend() && !m_busy;
    // V2.35 has no 0x91 (docs/V2.35.md): its drives would not answer, so it is not offered.
    const QString noOffset = absenceOf(Command::WriteEncoderOffset);
    m_writeOffset->setEnabled(can && noOffset.isEmpty());
    m_offsetNote->setText(noOffset.isEmpty()
                              ? tr("The offset is the raw position that reads as encoder 0. The "
                                   "spec's command table calls 0x91 a ROM write: it may write the "
                                   "drive's flash.")
                              : noOffset);
    m_clearAngle->setEnabled(can);
    m_zeroRom->setEnabled(can);
    const QString absent = absenceOf(Command::ClearTurnCount);
    m_clearTurns->setEnabled(can && absent.isEmpty());
    m_clearTurnsNote->setText(
        absent.isEmpty() ? tr("Whole turns of the multi-turn angle are dropped; the angle within "
                              "the present turn stays. Checked with read_multi_turn (0x92).")
                         : absent);
    m_useRaw->setEnabled(hasDrive() && m_encoder.has_value());
    m_bitsCombo->setEnabled(hasDrive());
    m_ratioSpin->setEnabled(hasDrive());
    m_offsetSpin->setEnabled(hasDrive());
}

bool EncoderView::confirm(const QString &key, const QString &title, const QString &question,
                          const QString &reason, const QString &accept)
{
    const int id = driveId();
    const bool yes = ConfirmDialog::ask(this, ConfirmRequest{key, title, question, reason, accept});
    // The dialog ran an event loop: the drive or the link may have changed meanwhile.
    if (yes && (!canSend() || driveId() != id || m_busy)) {
        setStatus(tr("The drive or the connection changed: nothing was sent."), true);
        return false;
    }
    if (!yes)
        setStatus(tr("Cancelled: nothing was sent."));
    return yes;
}

void EncoderView::writeOffset(int offset)
{
    if (!canSend() || m_busy)
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
    if (!confirm(QStringLiteral("write_encoder_offset"), tr("Write encoder offset"),
                 tr("Write encoder offset %1 to drive %2?").arg(offset).arg(driveId()),
                 tr("The zero of the encoder and of every angle moves, so position commands "
                    "go elsewhere afterwards. The spec's command table calls 0x91 a ROM write: "
                    "it may wear the drive's flash."),
                 tr("Write offset")))
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
                        const auto *e = payload<protocol::EncoderReading>(back);
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

void EncoderView::clearAngle()
{
    if (!canSend() || m_busy)
        return;
    if (!confirm(QStringLiteral("clear_angle"), tr("Clear motor angle"),
                 tr("Make the present position of drive %1 angle 0?").arg(driveId()),
                 tr("Multi-turn and single-turn angles restart from 0 here until power-off, so "
                    "absolute position commands go elsewhere afterwards."),
                 tr("Clear angle")))
        return;
    m_busy = true;
    refreshEnabled();
    const int id = driveId();
    setStatus(tr("Clearing the angle of drive %1\u2026").arg(id));
    readMultiTurn(bus::Priority::Operator, [this, id](double before) {
        tracker()->send(*build::plain(Command::ClearAngle, id).request,
                        [this, id, before](const bus::RequestResult &r) {
                            if (!r.ok()) {
                                m_busy = false;
                                setStatus(DriveText::failure(r), true);
                                refreshEnabled();
                                return;
                            }
                            onClearAcknowledged(id, before);
                        });
    });
}

void EncoderView::onClearAcknowledged(int id, double before)
{
    readMultiTurn(bus::Priority::Operator, [this, id, before](double after) {
        m_busy = false;
        if (id == driveId())
            showAngleCheck(AngleCheck::classify(before, after));
        refreshEnabled();
    });
}

void EncoderView::showAngleCheck(const AngleCheck &check)
{
    m_angleCheck = check;
    switch (check.outcome) {
    case AngleCheck::Outcome::Cleared:
        setStatus(tr("Angle cleared: the drive reads %1\u00b0 (was %2\u00b0).")
                      .arg(check.afterDeg, 0, 'f', 2)
                      .arg(check.beforeDeg, 0, 'f', 2));
        break;
    case AngleCheck::Outcome::AlreadyZero:
        setStatus(tr("The angle read %1\u00b0 before already: whether the drive applied 0x95 "
                     "cannot be told.")
                      .arg(check.beforeDeg, 0, 'f', 2));
        break;
    case AngleCheck::Outcome::Unchanged:
        setStatus(tr("The drive acknowledged 0x95 but its angle did not change (%1\u00b0): this "
                     "firmware ignores clear-angle. Use the encoder offset or 0x19 instead.")
                      .arg(check.afterDeg, 0, 'f', 2),
                  true);
        break;
    case AngleCheck::Outcome::ChangedNotZero:
        setStatus(tr("The angle changed from %1\u00b0 to %2\u00b0 but is not 0: was the motor "
                     "turning? Stop it and clear again.")
                      .arg(check.beforeDeg, 0, 'f', 2)
                      .arg(check.afterDeg, 0, 'f', 2),
                  true);
        break;
    }
    emit angleCheckFinished(check);
}

void EncoderView::writeZeroToRom()
{
    if (!canSend() || m_busy)
        return;
    if (!confirm(QStringLiteral("write_zero_rom"), tr("Write zero to ROM"),
                 tr("Store the present position of drive %1 as its zero in ROM?").arg(driveId()),
                 tr("It takes effect only after the drive is powered off and on again. It "
                    "writes the drive's flash, which wears with every write: do it once, "
                    "not as a routine."),
                 tr("Write zero to ROM")))
        return;
    m_busy = true;
    refreshEnabled();
    const int id = driveId();
    // Sent exactly once: a lost reply is reported, never retried.
    tracker()->send(
        *build::plain(Command::WriteZeroRom, id).request,
        [this, id](const bus::RequestResult &r) {
            m_busy = false;
            refreshEnabled();
            const auto *z = payload<protocol::ZeroWritten>(r);
            if (!z) {
                setStatus(DriveText::failure(r), true);
                emit zeroWriteFinished(false);
                return;
            }
            QString text = tr("Zero written to the ROM of drive %1. Power the drive off and on "
                              "for it to take effect.")
                               .arg(id);
            if (z->encoderOffset)
                text += QLatin1Char(' ') +
                        tr("The drive reports the new zero as encoder %1.").arg(*z->encoderOffset);
            setStatus(text);
            emit zeroWriteFinished(true);
        },
        bus::Priority::Operator, 0);
}

QString EncoderView::absenceOf(Command command) const
{
    if (!hasDrive())
        return QString();
    return GenerationNote::absence(motor(), command,
                                   command == Command::ClearTurnCount ? tr("clear turn count")
                                                                      : tr("the encoder offset"));
}

void EncoderView::clearTurnCount()
{
    if (!canSend() || m_busy)
        return;
    if (const QString absent = absenceOf(Command::ClearTurnCount); !absent.isEmpty()) {
        setStatus(absent, true);
        return;
    }
    // docs/V2.35.md names 0x93 only: neither RAM nor ROM, nor whether the motor must be off, is
    // documented, so the confirmation says so rather than guess.
    if (!confirm(QStringLiteral("clear_turn_count"), tr("Clear turn count"),
                 tr("Set the turn count of drive %1 to 0?").arg(driveId()),
                 tr("The multi-turn angle keeps only the angle within the present turn, so "
                    "multi-turn position commands go elsewhere afterwards. The V2.35 document "
                    "does not say whether this survives a power cycle (RAM or ROM) or whether "
                    "the motor must be off: stop the motor first."),
                 tr("Clear turn count")))
        return;
    m_busy = true;
    refreshEnabled();
    const int id = driveId();
    setStatus(tr("Clearing the turn count of drive %1\u2026").arg(id));
    readMultiTurn(bus::Priority::Operator, [this, id](double before) {
        // Sent once: whether it writes flash is not documented.
        tracker()->send(
            *build::plain(Command::ClearTurnCount, id).request,
            [this, id, before](const bus::RequestResult &r) {
                if (!r.ok()) {
                    m_busy = false;
                    setStatus(DriveText::failure(r), true);
                    refreshEnabled();
                    emit turnCountCleared(false);
                    return;
                }
                onTurnsCleared(id, before);
            },
            bus::Priority::Operator, 0);
    });
}

void EncoderView::onTurnsCleared(int id, double before)
{
    readMultiTurn(bus::Priority::Operator, [this, id, before](double after) {
        m_busy = false;
        refreshEnabled();
        if (id != driveId())
            return;
        // One output turn is 360 degrees times the gear ratio of rotor angle.
        const bool ok = std::abs(after) < 360.0 * m_ratio;
        setStatus(ok ? tr("Turn count of drive %1 cleared: the multi-turn angle reads %2\u00b0 "
                          "(was %3\u00b0).")
                           .arg(id)
                           .arg(after, 0, 'f', 2)
                           .arg(before, 0, 'f', 2)
                     : tr("Drive %1 acknowledged 0x93, but its multi-turn angle reads %2\u00b0 "
                          "(was %3\u00b0): more than one turn, so the turn count was not "
                          "cleared.")
                           .arg(id)
                           .arg(after, 0, 'f', 2)
                           .arg(before, 0, 'f', 2),
                  !ok);
        emit turnCountCleared(ok);
    });
}

} // namespace lk::ui
