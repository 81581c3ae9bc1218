#pragma once

#include <protocol/Command.h>

#include <QtCore/QPointer>
#include <QtCore/QVector>

namespace lk::bus {

class BusSession;

/// One holder's extra poll reads for one drive (BusSession::addPollExtras), kept in step
/// with what it wants: hold() adds them, or moves them to another session or drive, and does
/// nothing while they are already in place; release() and the destructor take them back.
class PollExtrasLease {
public:
    PollExtrasLease() = default;
    ~PollExtrasLease() { release(); }
    PollExtrasLease(const PollExtrasLease &) = delete;
    PollExtrasLease &operator=(const PollExtrasLease &) = delete;

    /// Read `commands` of drive `id` on `session` from now on.
    void hold(BusSession *session, int id, const QVector<protocol::Command> &commands);
    void release();
    /// The session's handle while held, else 0.
    quint64 handle() const { return m_handle; }

private:
    QPointer<BusSession> m_session; ///< where m_handle was added
    quint64 m_handle = 0;
    int m_id = 0;
};

} // namespace lk::bus
