#include "MultiTorquePanel.h"

#include "DriveSettingsStore.h"
#include "DriveText.h"
#include "GenerationNote.h"
#include "RequestTracker.h"

#include <bus/BusSession.h>
#include <motor/SeriesLimits.h>
#include <panels/SendBlockedTips.h>
#include <panels/StatusColors.h>
#include <protocol/CanLayout.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionGuard.h>
#include <text/CommandTitle.h>
#include <text/VerdictText.h>

#include <QtCore/QSet>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lk::ui {

namespace {
using protocol::Command;
using protocol::Generation;
using protocol::Link;
namespace build = protocol::build;

constexpr int kMaxDrives = safety::MultiTorqueGuard::kMaxDrives;
/// The frame's own scale and range: the old generation's 0xA1 (docs/CAN.md section 4.2).
constexpr double kAmpsPerLsb = protocol::kIqCommandAmpsPerLsb;
constexpr double kFrameMaxA = protocol::can::kMultiMotorIqMax * kAmpsPerLsb;

/// A drive's generation as the frame's rule takes it: known on CAN (chosen or told by a reply).
std::optional<Generation> canGeneration(const bus::KnownMotor &motor)
{
    return GenerationNote::generationOf(motor, Link::Can);
}

/// The same drive, known as well as before: a row built for it stays (and what was typed).
bool sameFacts(int id, const bus::KnownMotor &a, const bus::KnownMotor &b)
{
    return a.series == b.series && canGeneration(a) == canGeneration(b) &&
           DriveSettingsStore::driveKey(id, a) == DriveSettingsStore::driveKey(id, b);
}

QString idList(const QVector<int> &ids)
{
    QStringList out;
    for (int id : ids)
        out << QString::number(id);
    return out.join(QStringLiteral(", "));
}

double sentAmps(const protocol::Request &request)
{
    const auto *t = std::get_if<protocol::TorqueCommand>(&request.payload);
    return t ? t->iqA() : 0.0;
}
} // namespace

MultiTorquePanel::MultiTorquePanel(QWidget *parent)
    : QGroupBox(text::CommandTitle::multiTorque(), parent), m_tracker(new RequestTracker(this))
{
    setObjectName(QStringLiteral("multiTorque"));
    m_reason = new QLabel(this);
    m_reason->setObjectName(QStringLiteral("multiTorqueReason"));
    m_reason->setWordWrap(true);
    m_rowBox = new QWidget(this);
    m_grid = new QGridLayout(m_rowBox);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setColumnStretch(0, 1);
    m_send = new QPushButton(tr("Send"), this);
    m_send->setObjectName(QStringLiteral("multiTorqueSend"));
    m_send->setToolTip(tr("One frame (0x280) with the torque of every ticked drive, each checked "
                          "against its limits first; sent once, never repeated. The drives "
                          "must be in their Broadcast Mode (set with the vendor's tool)."));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("multiTorqueStop"));
    m_stop->setToolTip(tr("Motor Stop (0x81) to every drive of the last frame"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("multiTorqueStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    connect(m_send, &QPushButton::clicked, this, &MultiTorquePanel::send);
    connect(m_stop, &QPushButton::clicked, this, &MultiTorquePanel::stop);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_send);
    buttons->addWidget(m_stop);
    buttons->addStretch();
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_reason);
    layout->addWidget(m_rowBox);
    layout->addLayout(buttons);
    layout->addWidget(m_status);
    refreshAbsence();
    refreshEnabled();
}

MultiTorquePanel::~MultiTorquePanel() = default;

void MultiTorquePanel::setSession(bus::BusSession *session)
{
    if (session == m_session)
        return;
    disconnect(m_motorsConnection);
    disconnect(m_stopConnection);
    m_session = session;
    m_tracker->setSession(session);
    reset(QString());
    if (session) {
        m_motorsConnection = connect(session, &bus::BusSession::knownMotorsChanged, this,
                                     &MultiTorquePanel::setDrives);
        // Esc and the stop button reach every drive themselves; here nothing may stay ticked
        // for a later Send, and the last frame's replies are history.
        m_stopConnection = connect(session, &bus::BusSession::emergencyStopFinished, this, [this] {
            reset(tr("%1 Nothing is ticked now and every torque is back to 0 A.")
                      .arg(DriveText::stopReason(bus::SetpointStopReason::EmergencyStop)));
        });
    }
    setDrives(session ? session->knownMotors() : bus::KnownMotors{});
}

void MultiTorquePanel::setLimitsLookup(LimitsLookup lookup)
{
    m_limits = std::move(lookup);
    refreshRows();
    refreshEnabled();
}

void MultiTorquePanel::setLink(protocol::Link link)
{
    if (link == m_link)
        return;
    m_link = link;
    reset(QString());
}

void MultiTorquePanel::setConnected(bool canSend, const QString &whyNot)
{
    const QString why = canSend ? QString() : whyNot;
    if (canSend == m_canSend && why == m_whyNot)
        return;
    const bool changed = canSend != m_canSend;
    m_canSend = canSend;
    m_whyNot = why;
    if (!changed) {
        refreshEnabled();
        return;
    }
    // Ticks and torques typed for the link that went must not go out on the one that came.
    const bool anyTicked = std::any_of(m_rows.cbegin(), m_rows.cend(),
                                       [](const Row &r) { return r.tick->isChecked(); });
    const bool had = anyTicked || !stopTargets().isEmpty();
    reset(had ? tr("The connection changed: nothing is ticked now and every torque is back to "
                   "0 A.")
              : QString());
}

QString MultiTorquePanel::driveTitle(int id, const bus::KnownMotor &motor)
{
    if (motor.model && !motor.model->motorName.isEmpty())
        return tr("Drive %1 (%2)").arg(id).arg(motor.model->motorName);
    if (motor.series)
        return tr("Drive %1 (%2)").arg(id).arg(protocol::seriesName(*motor.series));
    return tr("Drive %1").arg(id);
}

QString MultiTorquePanel::rowRefusal(int id) const
{
    return m_rows.value(id).refusal;
}

QString MultiTorquePanel::replyText(int id) const
{
    const auto it = m_rows.constFind(id);
    return it == m_rows.cend() ? QString() : it->reply->text();
}

QString MultiTorquePanel::statusText() const
{
    return m_status->text();
}

QVector<int> MultiTorquePanel::stopTargets() const
{
    QVector<int> ids = m_lastFrame;
    for (int id : m_awaited) {
        if (!ids.contains(id))
            ids.append(id);
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

void MultiTorquePanel::setDrives(const bus::KnownMotors &motors)
{
    m_motors = motors;
    for (int id = 1; id <= kMaxDrives; ++id) {
        const auto known = motors.constFind(id);
        const auto row = m_rows.constFind(id);
        if (known == motors.cend()) {
            removeRow(id);
            continue;
        }
        if (row != m_rows.cend() && sameFacts(id, row->motor, *known))
            continue;
        removeRow(id);
        buildRow(id, *known);
    }
    refreshAbsence();
    refreshEnabled();
}

void MultiTorquePanel::buildRow(int id, const bus::KnownMotor &motor)
{
    Row r;
    r.motor = motor;
    r.tick = new QCheckBox(driveTitle(id, motor), m_rowBox);
    r.tick->setObjectName(QStringLiteral("multiTorqueTick%1").arg(id));
    r.iq = new QDoubleSpinBox(m_rowBox);
    r.iq->setObjectName(QStringLiteral("multiTorqueIq%1").arg(id));
    r.iq->setDecimals(2);
    r.iq->setSingleStep(0.1);
    r.iq->setSuffix(QStringLiteral(" A"));
    r.reply = new QLabel(tr("no reply yet"), m_rowBox);
    r.reply->setObjectName(QStringLiteral("multiTorqueReply%1").arg(id));
    r.reply->setWordWrap(true);
    r.reply->setIndent(20);
    const int line = 2 * (id - 1); // fixed places by ID: rows come and go without re-layout
    m_grid->addWidget(r.tick, line, 0);
    m_grid->addWidget(r.iq, line, 1);
    m_grid->addWidget(r.reply, line + 1, 0, 1, 2);
    refreshRow(id, *m_rows.insert(id, r));
}

void MultiTorquePanel::removeRow(int id)
{
    const auto it = m_rows.find(id);
    if (it == m_rows.end())
        return;
    delete it->tick;
    delete it->iq;
    delete it->reply;
    m_rows.erase(it);
}

std::optional<safety::SoftLimits> MultiTorquePanel::limitsOf(int id, const bus::KnownMotor &motor,
                                                             QString *why) const
{
    if (m_limits)
        return m_limits(id, motor, why);
    return safety::SoftLimits::defaults(motor.series);
}

QString MultiTorquePanel::refusalOf(int id, const bus::KnownMotor &motor, double *bound) const
{
    *bound = 0;
    const std::optional<Generation> generation = canGeneration(motor);
    if (!generation)
        return tr("CAN generation not known: select drive %1 in the drive list and choose its "
                  "series and CAN generation (old: 0x140 replies) below it")
            .arg(id);
    if (*generation != Generation::V2_3)
        return tr("CAN V2.36 documents no multi-motor frame");
    if (!motor.series)
        return tr("series not known: select drive %1 in the drive list and choose its series "
                  "below it")
            .arg(id);
    QString why;
    const std::optional<safety::SoftLimits> limits = limitsOf(id, motor, &why);
    if (!limits)
        return why;
    // Whether the series has torque at all (MS has none), as a torque command is checked.
    const protocol::DecodeContext context{*motor.series, Generation::V2_3, Link::Can};
    const safety::Verdict v =
        safety::MotionGuard::check(*build::torque(id, 0, context).request, motor.series, *limits);
    if (!v.allowed())
        return text::VerdictText::verdict(v, motor.series);
    const double top =
        std::min({limits->maxTorqueA, motor::seriesLimits(*motor.series).maxCurrentA, kFrameMaxA});
    // Whole steps of the frame's scale: a bound the wire rounds up to would be refused.
    *bound = std::floor(top / kAmpsPerLsb + 1e-9) * kAmpsPerLsb;
    return {};
}

void MultiTorquePanel::refreshRows()
{
    for (auto it = m_rows.begin(); it != m_rows.end(); ++it)
        refreshRow(it.key(), *it);
}

void MultiTorquePanel::refreshRow(int id, Row &row)
{
    double bound = 0;
    row.refusal = refusalOf(id, row.motor, &bound);
    const bool usable = row.refusal.isEmpty();
    if (!usable)
        row.tick->setChecked(false);
    row.tick->setEnabled(usable);
    row.iq->setEnabled(usable);
    row.iq->setRange(-bound, bound);
    row.iq->setToolTip(usable
                           ? tr("Torque current of drive %1: at most %2 A either way (its limits)")
                                 .arg(id)
                                 .arg(bound, 0, 'f', 2)
                           : row.refusal);
    row.tick->setToolTip(row.refusal);
    if (!usable)
        row.reply->setText(row.refusal);
}

void MultiTorquePanel::refreshAbsence()
{
    m_absence.clear();
    if (m_link != Link::Can) {
        m_absence = tr("No such frame on RS485: the multi-motor torque frame (0x280) is a CAN "
                       "frame of the old generation.");
        return;
    }
    if (m_rows.isEmpty()) {
        m_absence = tr("No drive of ID 1..4 is on the bus: the frame (0x280) has slots for IDs "
                       "1..4 only.");
        return;
    }
    int v236 = 0;
    int unknown = 0;
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        const std::optional<Generation> g = canGeneration(it->motor);
        if (g == Generation::V2_3)
            return; // one drive of the old generation: the frame can be used
        if (!g && unknown == 0)
            unknown = it.key();
        if (g && v236 == 0)
            v236 = it.key();
    }
    // A drive of unknown generation may be an old one: that is the sentence to act on.
    m_absence = unknown > 0
                    ? tr("The CAN generation of drive %1 is not known: select it in the drive "
                         "list and choose its series and CAN generation (old: 0x140 replies) "
                         "below it.")
                          .arg(unknown)
                    : tr("Drive %1 speaks CAN V2.36, which documents no multi-motor frame "
                         "(0x280).")
                          .arg(v236);
}

bool MultiTorquePanel::canUse() const
{
    return m_session && m_canSend && m_absence.isEmpty() && m_awaited.isEmpty();
}

void MultiTorquePanel::refreshEnabled()
{
    QString reason = m_absence;
    if (reason.isEmpty() && !m_canSend)
        reason = m_whyNot.isEmpty() ? tr("Disconnected: nothing can be sent.") : m_whyNot;
    m_reason->setText(reason);
    m_reason->setVisible(!reason.isEmpty());
    m_rowBox->setVisible(m_absence.isEmpty());
    m_send->setVisible(m_absence.isEmpty()); // absent: the one line says it all
    m_stop->setVisible(m_absence.isEmpty());
    m_send->setEnabled(canUse());
    m_stop->setEnabled(m_session && m_canSend && !stopTargets().isEmpty());
    SendBlockedTips::apply(this, m_whyNot);
}

void MultiTorquePanel::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, palette(), true) : QString());
}

void MultiTorquePanel::refuse(const QString &why)
{
    setStatus(why, true);
    emit refused(why);
}

void MultiTorquePanel::send()
{
    if (!canUse())
        return;
    QVector<protocol::Request> torques;
    QMap<int, safety::MultiTorqueDrive> drives;
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        if (!it->tick->isChecked())
            continue;
        const int id = it.key();
        // The limits as they are now (the Control view may have applied others since).
        QString why;
        const std::optional<safety::SoftLimits> limits = limitsOf(id, it->motor, &why);
        if (!limits) {
            refuse(why);
            return;
        }
        safety::MultiTorqueDrive d;
        d.series = it->motor.series;
        d.generation = canGeneration(it->motor);
        d.limits = *limits;
        drives.insert(id, d);
        const protocol::DecodeContext context{d.series.value_or(protocol::Series::MF),
                                              Generation::V2_3, Link::Can};
        const protocol::BuildResult built = build::torque(id, it->iq->value(), context);
        if (!built.ok()) {
            refuse(tr("Refused: drive %1: %2. Nothing sent.").arg(id).arg(built.error.message()));
            return;
        }
        torques.append(*built.request);
    }
    QSet<int> onBus;
    for (auto it = m_motors.cbegin(); it != m_motors.cend(); ++it)
        onBus.insert(it.key());
    const safety::MultiTorqueVerdict verdict = safety::MultiTorqueGuard::check(
        torques, m_link, [&drives](int id) { return drives.value(id); }, onBus);
    if (!verdict.allowed()) {
        refuse(refusalText(verdict, drives));
        return;
    }
    QStringList what;
    m_awaited.clear();
    for (const protocol::Request &t : std::as_const(torques)) {
        m_awaited.append(t.id);
        what << tr("drive %1 %2 A").arg(t.id).arg(sentAmps(t), 0, 'f', 2);
    }
    const quint64 epoch = m_epoch;
    m_session->sendMultiTorque(bus::MultiTorqueRequest{torques}, this,
                               [this, epoch](const bus::MultiTorqueResult &r) {
                                   if (epoch == m_epoch) // else reset() since: history
                                       onFrameEnded(r);
                               });
    setStatus(tr("Multi-motor torque (0x280) handed to the bus: %1. Waiting for the "
                 "replies\u2026")
                  .arg(what.join(QStringLiteral(", "))));
    refreshEnabled();
}

QString MultiTorquePanel::refusalText(const safety::MultiTorqueVerdict &v,
                                      const QMap<int, safety::MultiTorqueDrive> &drives) const
{
    using P = safety::MultiTorqueProblem;
    const auto row = m_rows.constFind(v.id);
    switch (v.problem) {
    case P::NoDrive:
        return tr("Nothing is ticked: tick the drives the frame is for. Nothing sent.");
    case P::UnnamedDrive:
        // The frame has a slot for each of IDs 1..4: an unticked drive there gets 0 A.
        if (row != m_rows.cend() && !row->refusal.isEmpty())
            return tr("Refused: drive %1 is on the bus, would get 0 A from this frame (it has a "
                      "slot for each of IDs 1..4) and cannot be ticked: %2. Nothing sent.")
                .arg(v.id)
                .arg(row->refusal);
        return tr("Refused: drive %1 is on the bus and would get 0 A from this frame (it has a "
                  "slot for each of IDs 1..4). Tick drive %1 with 0 A if zero torque is meant. "
                  "Nothing sent.")
            .arg(v.id);
    case P::UnknownGeneration:
        return tr("Refused: the CAN generation of drive %1 is not known: choose it below the "
                  "drive list. Nothing sent.")
            .arg(v.id);
    case P::V236:
        return tr("Refused: drive %1 speaks CAN V2.36, which documents no multi-motor frame. "
                  "Nothing sent.")
            .arg(v.id);
    case P::Limit:
        if (v.verdict.kind != safety::LimitKind::UnknownSeries)
            return tr("Refused: drive %1: %2. Nothing sent.")
                .arg(v.id)
                .arg(text::VerdictText::verdict(v.verdict, drives.value(v.id).series));
        return tr("Refused: the series of drive %1 is not known: choose it below the drive "
                  "list. Nothing sent.")
            .arg(v.id);
    default:
        return tr("Refused: %1").arg(safety::MultiTorqueGuard::text(v));
    }
}

void MultiTorquePanel::onFrameEnded(const bus::MultiTorqueResult &result)
{
    m_awaited.clear();
    if (result.refused()) {
        setStatus(tr("Refused by the bus: %1").arg(result.reason), true);
    } else if (result.attempts == 0) {
        setStatus(tr("Not sent: %1").arg(result.reason), true);
    } else {
        QStringList sent;
        QVector<int> answered;
        QVector<int> silent;
        m_lastFrame.clear();
        for (const bus::RequestResult &d : result.drives) {
            const int id = d.request.id;
            m_lastFrame.append(id);
            sent << tr("drive %1 %2 A").arg(id).arg(sentAmps(d.request), 0, 'f', 2);
            const auto *s = replyPayload<protocol::State2>(d);
            (s ? answered : silent).append(id);
            const auto row = m_rows.find(id);
            if (row == m_rows.end())
                continue;
            // Each value as the drive told it; no reply is said, never shown as a 0.
            row->reply->setText(s ? tr("iq %1 A, %2 dps, %3 °C")
                                        .arg(s->iqA(), 0, 'f', 2)
                                        .arg(s->speedDps)
                                        .arg(s->temperatureC)
                                  : tr("no reply to the last frame"));
        }
        QString text =
            tr("Sent multi-motor torque (0x280): %1.").arg(sent.join(QStringLiteral(", ")));
        if (!answered.isEmpty())
            text += QLatin1Char(' ') + tr("Answered: drive(s) %1.").arg(idList(answered));
        if (!silent.isEmpty())
            text += QLatin1Char(' ') +
                    tr("No reply from drive(s) %1 (not in Broadcast Mode, or absent): they may "
                       "have acted on it all the same; Stop or Esc stops them.")
                        .arg(idList(silent));
        setStatus(text, !silent.isEmpty());
    }
    refreshEnabled();
    emit frameFinished(result);
}

void MultiTorquePanel::stop()
{
    const QVector<int> targets = stopTargets();
    if (!m_session || !m_canSend || targets.isEmpty())
        return;
    for (int id : targets) {
        // Ahead of queued work, as the Control view's Stop.
        m_tracker->send(
            *build::plain(Command::MotorStop, id).request,
            [this](const bus::RequestResult &r) {
                if (!r.ok())
                    setStatus(statusText() + QLatin1Char(' ') + DriveText::failure(r), true);
            },
            bus::Priority::Emergency);
    }
    setStatus(tr("Sent Motor Stop (0x81) to drive(s) %1.").arg(idList(targets)));
}

void MultiTorquePanel::reset(const QString &why)
{
    ++m_epoch;
    m_awaited.clear();
    m_lastFrame.clear();
    m_tracker->forgetAll();
    for (Row &r : m_rows) {
        r.tick->setChecked(false);
        r.iq->setValue(0);
        r.reply->setText(tr("no reply yet"));
    }
    refreshRows();
    refreshAbsence();
    refreshEnabled();
    setStatus(why);
}

} // namespace lk::ui
