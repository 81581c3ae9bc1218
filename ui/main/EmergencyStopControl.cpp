#include "EmergencyStopControl.h"

#include "BusController.h"
#include "CommandedMotion.h"
#include "EmergencyKeyFilter.h"
#include "EmergencyStopReport.h"

#include <panels/BusModel.h>
#include <panels/MessageBanner.h>

#include <bus/BusSession.h>

#include <protocol/Checksum.h>
#include <text/VerdictText.h>

#include <QtCore/QLoggingCategory>
#include <QtCore/QTime>
#include <QtWidgets/QApplication>

#include <algorithm>

namespace lk::ui {

namespace {
Q_LOGGING_CATEGORY(lcStop, "lk.studio.stop")
} // namespace

EmergencyStopControl::EmergencyStopControl(BusController *controller, CommandedMotion *motion,
                                           MessageBanner *banner, QObject *parent)
    : QObject(parent), m_controller(controller), m_motion(motion), m_banner(banner),
      m_keys(new EmergencyKeyFilter(this))
{
    qApp->installEventFilter(m_keys);
    connect(m_keys, &EmergencyKeyFilter::escapePressed, this, &EmergencyStopControl::stop);
    bus::BusSession *session = m_controller->session();
    connect(session, &bus::BusSession::emergencyStopProgress, this,
            &EmergencyStopControl::onProgress);
    connect(session, &bus::BusSession::emergencyStopFinished, this,
            &EmergencyStopControl::onFinished);
    connect(session, &bus::BusSession::connectionChanged, this,
            &EmergencyStopControl::onConnectionChanged);
    connect(session, &bus::BusSession::telemetryReceived, this, &EmergencyStopControl::onTelemetry);
    connect(m_banner, &MessageBanner::entryDismissed, this, [this](const QString &key) {
        if (key != entryKey())
            return;
        m_shown.reset();
        m_resend.reset(); // the operator has dealt with it: nothing goes out later
    });
}

EmergencyStopControl::~EmergencyStopControl()
{
    qApp->removeEventFilter(m_keys);
}

void EmergencyStopControl::stop()
{
    emit halting(tr("Emergency stop."));
    // Listening (also while its link is down): the bus would refuse the stop; nothing is asked.
    if (m_controller->session()->linkMode() == bus::LinkMode::ListenOnly) {
        showListenOnly(); // nothing reaches the bus: say so, and who must stop the machine
        return;
    }
    Pending p;
    // Whom to reach first: the drives on screen, those the bus knows, and those lkstudio told
    // to move (a scan may have just emptied the first two). The bus adds the drives it saw
    // answer or move, then every other ID.
    p.watched = m_controller->model()->ids() + m_motion->movingIds();
    for (int id : m_controller->session()->knownMotors().keys())
        p.watched.append(id);
    std::sort(p.watched.begin(), p.watched.end());
    p.watched.erase(std::unique(p.watched.begin(), p.watched.end()), p.watched.end());
    for (int id : m_motion->movingIds())
        p.commanded << m_motion->driveText(id);
    m_resend.reset(); // this stop replaces one still waiting for the link
    send(p);
}

void EmergencyStopControl::send(const Pending &p)
{
    m_shown.reset();
    const bool open = m_controller->session()->connection().isOpen();
    const quint64 ticket = m_controller->emergencyStop(p.watched);
    m_pending.insert(ticket, p);
    if (open) {
        Outcome underWay;
        underWay.remaining = protocol::kMaxId - protocol::kMinId + 1;
        report(p, underWay);
    }
}

void EmergencyStopControl::onProgress(quint64 ticket, const QVector<int> &acknowledged,
                                      const QVector<int> &silent, int remaining)
{
    const auto it = m_pending.constFind(ticket);
    if (it == m_pending.cend())
        return;
    Outcome outcome;
    outcome.acknowledged = acknowledged;
    outcome.silent = silent;
    outcome.remaining = remaining;
    report(*it, outcome);
}

void EmergencyStopControl::onFinished(quint64 ticket, const QVector<int> &acknowledged,
                                      const QVector<int> &silent, const QVector<int> &unsent)
{
    const auto it = m_pending.find(ticket);
    if (it == m_pending.end())
        return;
    Pending p = *it;
    m_pending.erase(it);
    Outcome outcome;
    outcome.acknowledged = acknowledged;
    outcome.silent = silent;
    outcome.unsent = unsent;
    if (!silent.isEmpty() && unsent.size() == silent.size() && acknowledged.isEmpty()) {
        // Nothing went out: it goes out once this port is back (a stop pressed for one
        // machine is not sent to another).
        p.pressedWhileDisconnectedAt = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
        m_resend = p;
        m_resendPort = m_lastPort;
    }
    m_shown.emplace(p, outcome);
    report(p, outcome);
    emit reported();
}

void EmergencyStopControl::onConnectionChanged(const bus::ConnectionStatus &status)
{
    if (!status.isOpen())
        return;
    const QString port = portOf(status.description);
    const bool samePort = m_resendPort.isEmpty() || port == m_resendPort;
    m_lastPort = port;
    if (!m_resend || !samePort)
        return;
    if (!status.canTransmit) {
        // Reconnected listen-only: the stop pressed while disconnected cannot go out either.
        showListenOnly();
        return;
    }
    const Pending p = *m_resend;
    m_resend.reset();
    qCWarning(lcStop).noquote() << "emergency stop pressed at" << p.pressedWhileDisconnectedAt
                                << "while disconnected: sent now that" << port << "is open";
    emit halting(tr("Emergency stop."));
    send(p);
}

QString EmergencyStopControl::portOf(const QString &description)
{
    return description.section(QStringLiteral(" @ "), 0, 0);
}

void EmergencyStopControl::onTelemetry(const bus::TelemetryBatch &batch)
{
    if (!m_shown || !m_controller->session()->connection().isOpen())
        return;
    auto &[p, outcome] = *m_shown;
    const QVector<int> moving = EmergencyStopReport::mayBeMoving(p, outcome);
    bool changed = false;
    for (const bus::TelemetrySample &s : batch) {
        if (moving.contains(s.id) && !outcome.sinceStopped.contains(s.id) &&
            s.has(bus::TelemetryField::Speed) && s.speedDps == 0) {
            outcome.sinceStopped.append(s.id);
            changed = true;
        }
    }
    if (changed)
        report(p, outcome);
}

void EmergencyStopControl::showListenOnly()
{
    // Not resent later either: taking the bus over is the user's own, separate decision.
    m_resend.reset();
    m_shown.reset();
    m_banner->setEntry(entryKey(), MessageBanner::Level::Error,
                       text::VerdictText::listenOnlyStop().toHtmlEscaped());
    qCWarning(lcStop) << "emergency stop while listening only: nothing was sent";
    emit reported();
}

void EmergencyStopControl::report(const Pending &p, const Outcome &outcome)
{
    const EmergencyStopReport::Text text = EmergencyStopReport::compose(p, outcome);
    m_banner->setEntry(entryKey(), text.level, text.html);
}

} // namespace lk::ui
