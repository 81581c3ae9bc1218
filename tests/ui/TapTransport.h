#pragma once

// The transport of the listen-only window tests: it wraps the one the session would use (the
// built-in simulated bus), counts every byte the bus hands it to send - the figure that must
// stay 0 while listening - and plays what a tap on a running machine's bus hears: requests of
// another master and its drives' replies (hear()), both on the one received stream.

#include <bus/TransportFactory.h>
#include <transport/Transport.h>

#include <QtCore/QMetaObject>
#include <QtCore/QMutex>
#include <QtCore/QPointer>

#include <atomic>
#include <memory>

namespace lk::uitest {

/// What the tapped transports of one test share with it (they live on the bus thread).
struct TapLine {
    std::atomic<qint64> written{0}; ///< bytes handed to write(), over every transport made
    std::atomic<int> opened{0};     ///< open() calls
    std::atomic<int> readOnlyOpens{0};
    QMutex mutex;
    QPointer<transport::Transport> current; ///< the transport made last

    /// Bytes heard on the wire, delivered on the bus thread as the transport's received bytes.
    bool hear(const QByteArray &bytes)
    {
        const QMutexLocker lock(&mutex);
        if (!current)
            return false;
        transport::Transport *t = current.data();
        return QMetaObject::invokeMethod(
            t, [t, bytes] { emit t->bytesReceived(bytes); }, Qt::QueuedConnection);
    }
};

class TapTransport : public transport::Transport {
public:
    TapTransport(std::unique_ptr<transport::Transport> inner, std::shared_ptr<TapLine> line)
        : m_inner(std::move(inner)), m_line(std::move(line))
    {
        using T = transport::Transport;
        connect(m_inner.get(), &T::bytesReceived, this, &T::bytesReceived);
        connect(m_inner.get(), &T::stateChanged, this, &T::stateChanged);
        connect(m_inner.get(), &T::errorOccurred, this, &T::errorOccurred);
    }

    /// The factory wrapper for BusController::addFactoryWrapper.
    static bus::TransportFactory wrap(bus::TransportFactory inner, std::shared_ptr<TapLine> line)
    {
        return [inner = std::move(inner), line](int baud) -> std::unique_ptr<Transport> {
            auto made = std::make_unique<TapTransport>(inner(baud), line);
            const QMutexLocker lock(&line->mutex);
            line->current = made.get();
            return made;
        };
    }

    bool open() override
    {
        ++m_line->opened;
        if (isReadOnly())
            ++m_line->readOnlyOpens;
        m_inner->setReadOnly(isReadOnly());
        return m_inner->open();
    }
    void close() override { m_inner->close(); }
    void write(const QByteArray &bytes) override
    {
        m_line->written += bytes.size(); // counted before anything may refuse them
        m_inner->write(bytes);
    }
    State state() const override { return m_inner->state(); }
    int baud() const override { return m_inner->baud(); }
    QString description() const override { return m_inner->description(); }

private:
    std::unique_ptr<transport::Transport> m_inner;
    std::shared_ptr<TapLine> m_line;
};

} // namespace lk::uitest
