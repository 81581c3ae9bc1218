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
    m_session = session;
    forgetAll();
}

quint64 RequestTracker::send(const protocol::Request &request, Callback callback,
                             bus::Priority priority, int retries)
{
    if (!m_session)
        return 0;
    // The epoch, not the ticket alone, says whether a result is still wanted: tickets of
    // another session may repeat the numbers.
    auto done = [this, epoch = m_epoch,
                 callback = std::move(callback)](const bus::RequestResult &result) {
        if (epoch != m_epoch || !m_pending.remove(result.ticket))
            return;
        emit pendingChanged(pendingCount());
        if (callback)
            callback(result);
    };
    const quint64 ticket = m_session->send(request, this, std::move(done), priority, retries);
    m_pending.insert(ticket);
    emit pendingChanged(pendingCount());
    return ticket;
}

void RequestTracker::forgetAll()
{
    ++m_epoch;
    if (m_pending.isEmpty())
        return;
    m_pending.clear();
    emit pendingChanged(0);
}

} // namespace lk::ui
