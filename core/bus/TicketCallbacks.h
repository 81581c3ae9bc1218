#pragma once

#include <QtCore/QHash>
#include <QtCore/QMetaObject>
#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QThread>

#include <functional>
#include <utility>

namespace lk::bus {

/// Callbacks waiting for the end of a ticket, each run at most once, on its context's thread,
/// and not at all once its context is gone (the semantics of a connect() with a context).
///
/// Lives in BusSession, which hears every end once on its own thread and hands it here: no
/// listener has to watch every completion for its own ticket.
template <typename... Args> class TicketCallbacks {
public:
    using Callback = std::function<void(const Args &...)>;

    void add(quint64 ticket, QObject *context, Callback callback)
    {
        if (context && callback)
            m_waiting.insert(ticket, Entry{context, std::move(callback)});
    }

    /// The callback given for `ticket`, out of the table, wrapped so that it keeps the rules
    /// above when called; empty when there is none. Taken before its end is announced, the
    /// callback is not lost if a listener closes the session meanwhile.
    Callback take(quint64 ticket)
    {
        const auto it = m_waiting.find(ticket);
        if (it == m_waiting.end())
            return {};
        Entry e = std::move(it.value());
        m_waiting.erase(it);
        return [e = std::move(e)](const Args &...args) { deliver(e, args...); };
    }

    /// Forget every callback without running it.
    void clear() { m_waiting.clear(); }
    int size() const { return static_cast<int>(m_waiting.size()); }

private:
    struct Entry {
        QPointer<QObject> context;
        Callback callback;
    };

    static void deliver(const Entry &e, const Args &...args)
    {
        if (!e.context)
            return;
        if (e.context->thread() == QThread::currentThread()) {
            e.callback(args...);
            return;
        }
        // Posted to the context, so that it runs there; Qt discards the call if the context
        // is deleted first.
        QMetaObject::invokeMethod(
            e.context.data(),
            [context = e.context, callback = e.callback, args...] {
                if (context)
                    callback(args...);
            },
            Qt::QueuedConnection);
    }
    QHash<quint64, Entry> m_waiting;
};

} // namespace lk::bus
