#include "PollExtrasLease.h"

#include "BusSession.h"

namespace lk::bus {

void PollExtrasLease::hold(BusSession *session, int id, const QVector<protocol::Command> &commands)
{
    // A session that was closed meanwhile dropped the extras: its handle no longer counts.
    if (m_handle && m_session == session && m_id == id && session->hasPollExtras(m_handle))
        return;
    release();
    m_session = session;
    m_id = id;
    m_handle = session->addPollExtras(id, commands);
}

void PollExtrasLease::release()
{
    if (m_session && m_handle)
        m_session->removePollExtras(m_handle);
    m_session.clear();
    m_handle = 0;
    m_id = 0;
}

} // namespace lk::bus
