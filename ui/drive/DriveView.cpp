#include "DriveView.h"

#include "RequestTracker.h"

#include <bus/BusSession.h>
#include <panels/SendBlockedTips.h>

namespace lk::ui {

DriveView::DriveView(QWidget *parent) : QWidget(parent), m_tracker(new RequestTracker(this)) {}

bus::BusSession *DriveView::session() const
{
    return m_session.data();
}

void DriveView::setSession(bus::BusSession *session)
{
    if (m_session == session)
        return;
    m_session = session;
    m_tracker->setSession(session);
    notify(Change::Session);
}

void DriveView::setDrive(int id, const bus::KnownMotor &motor)
{
    if (id <= 0) {
        clearDrive();
        return;
    }
    const bool sameId = id == m_id;
    m_id = id;
    m_motor = motor;
    m_motor.id = id;
    if (!sameId)
        m_tracker->forgetAll(); // results for the previous drive must not land on this one
    notify(sameId ? Changes(Change::MotorInfo) : Changes(Change::Drive));
}

void DriveView::clearDrive()
{
    if (m_id == 0)
        return;
    m_id = 0;
    m_motor = bus::KnownMotor{};
    m_tracker->forgetAll();
    notify(Change::Drive);
}

void DriveView::setConnected(bool connected, const QString &whyNot)
{
    const QString why = connected ? QString() : whyNot;
    if (m_connected == connected && m_whyNot == why)
        return;
    m_connected = connected;
    m_whyNot = why;
    if (!connected)
        m_tracker->forgetAll(); // they end Disconnected or Cancelled anyway
    notify(Change::Connection);
}

void DriveView::setLink(protocol::Link link)
{
    if (m_link == link)
        return;
    m_link = link;
    notify(Change::MotorInfo);
}

std::optional<protocol::Series> DriveView::series() const
{
    if (m_motor.series)
        return m_motor.series;
    if (m_session && m_id > 0)
        return m_session->series(m_id);
    return std::nullopt;
}

QString DriveView::cannotSendText(const QString &disconnected) const
{
    return m_whyNot.isEmpty() ? disconnected : m_whyNot;
}

bool DriveView::canSendToDrive() const
{
    return m_session && m_connected && m_id > 0;
}

QString DriveView::driveTitle() const
{
    if (m_id <= 0)
        return tr("No drive selected");
    if (m_motor.model && !m_motor.model->motorName.isEmpty())
        return tr("Drive %1 (%2)").arg(m_id).arg(m_motor.model->motorName);
    return tr("Drive %1").arg(m_id);
}

void DriveView::notify(Changes changes)
{
    contextChanged(changes);
    SendBlockedTips::apply(this, m_whyNot);
}

} // namespace lk::ui
