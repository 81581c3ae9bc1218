#pragma once

#include <bus/Priority.h>
#include <bus/RequestResult.h>
#include <protocol/Request.h>

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QSet>

#include <functional>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

/// The reply's payload of type T, for a request that completed with a reply carrying one;
/// nullptr otherwise (failed, or another payload).
template <typename T> const T *replyPayload(const bus::RequestResult &r)
{
    return r.ok() && r.reply ? std::get_if<T>(&r.reply->payload) : nullptr;
}

/// Sends a view's requests through a BusSession (each with its callback) and counts those
/// still awaited, so that the view can disable its buttons meanwhile and drop the results of
/// requests made for another drive or link. Never waits.
class RequestTracker : public QObject {
    Q_OBJECT
public:
    using Callback = std::function<void(const bus::RequestResult &)>;

    explicit RequestTracker(QObject *parent = nullptr);

    /// Switches sessions; callbacks of requests sent on the old one are dropped.
    void setSession(bus::BusSession *session);
    bus::BusSession *session() const;

    /// Queues `request`; `callback` runs once with its result. Returns the ticket, or 0 when
    /// there is no session (nothing sent, the callback never runs).
    quint64 send(const protocol::Request &request, Callback callback = {},
                 bus::Priority priority = bus::Priority::Operator, int retries = -1);
    /// Forget every pending callback (the drive or the connection changed): late results
    /// of those requests are ignored.
    void forgetAll();

    int pendingCount() const { return static_cast<int>(m_pending.size()); }
    bool isPending(quint64 ticket) const { return m_pending.contains(ticket); }

signals:
    /// The number of requests still awaited changed (e.g. to disable buttons meanwhile).
    void pendingChanged(int count);

private:
    QPointer<bus::BusSession> m_session;
    QSet<quint64> m_pending;
    quint64 m_epoch = 0; ///< forgetAll() count: results of requests sent before it are dropped
};

} // namespace lk::ui
