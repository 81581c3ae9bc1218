#include "RequestTracker.h"

#include <bus/BusSession.h>

namespace lk::ui {

RequestTracker::RequestTracker(QObject *parent) : QObject(parent) {}

bus::BusSession *RequestTracker::session() const
{
    return m_session.data();
}

void RequestTracker::setSession(bus::BusSession *session)
{
    if (m_session == session)
        return;
    disconnect(m_connection);
    m_session = session;
    forgetAll();
    if (session)
        m_connection = connect(session, &bus::BusSession::requestCompleted, this,
                               &RequestTracker::onCompleted);
}

quint64 RequestTracker::send(const protocol::Request &request, Callback callback,
                             bus::Priority priority, int retries)
{
    if (!m_session)
        return 0;
    const quint64 ticket = m_session->send(request, priority, retries);
    m_pending.insert(ticket, std::move(callback));
    emit pendingChanged(pendingCount());
    return ticket;
}

void RequestTracker::forgetAll()
{
    if (m_pending.isEmpty())
        return;
    m_pending.clear();
    emit pendingChanged(0);
}

void RequestTracker::onCompleted(const bus::RequestResult &result)
{
    const auto it = m_pending.find(result.ticket);
    if (it == m_pending.end())
        return;
    // Out of the table before the call: the callback may send again or forget everything.
    const Callback callback = std::move(it.value());
    m_pending.erase(it);
    emit pendingChanged(pendingCount());
    if (callback)
        callback(result);
}

} // namespace lk::ui
