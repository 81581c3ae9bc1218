#include "FakeTransport.h"

#include <protocol/StreamParser.h>

#include <QtCore/QMetaObject>
#include <QtCore/QPointer>
#include <QtCore/QTimer>

namespace lk::bustest {

using transport::TransportError;

FakeTransport::FakeTransport(int baud, std::shared_ptr<FakeLog> log, QObject *parent)
    : Transport(parent), m_baud(baud), m_log(log ? std::move(log) : std::make_shared<FakeLog>())
{
}

bool FakeTransport::open()
{
    if (m_failOpen) {
        emit errorOccurred(TransportError{TransportError::Kind::NoSuchPort,
                                          QStringLiteral("No serial port /dev/fake.")});
        return false;
    }
    {
        QMutexLocker lock(&m_log->mutex);
        ++m_log->opens;
        m_log->readOnly.append(isReadOnly());
    }
    setState(State::Open);
    return true;
}

void FakeTransport::close()
{
    setState(State::Closed);
}

QString FakeTransport::description() const
{
    return QStringLiteral("fake @ %1").arg(m_baud);
}

QByteArray FakeTransport::defaultReply(const protocol::Frame &request) const
{
    return m_drives.reply(request);
}

void FakeTransport::write(const QByteArray &bytes)
{
    // Every byte that reaches a transport is logged, read-only or not: a listen-only test
    // counts here what would have gone on the wire.
    if (m_state != State::Open)
        return;
    {
        QMutexLocker lock(&m_log->mutex);
        m_log->written.append(bytes);
    }
    const int index = m_index++;
    if (m_localEcho)
        deliver(bytes, 0);
    protocol::StreamParser parser;
    protocol::Frame request;
    bool haveFrame = false;
    parser.feed(bytes, [&](const protocol::ParseEvent &ev) {
        if (ev.isFrame && !haveFrame) {
            request = ev.frame;
            haveFrame = true;
        }
    });
    if (!haveFrame)
        return;
    const QByteArray reply = m_responder ? m_responder(request, index) : defaultReply(request);
    if (!reply.isEmpty())
        deliver(reply, m_delayMs);
}

void FakeTransport::deliver(const QByteArray &bytes, int delayMs)
{
    auto arrive = [this, bytes] {
        if (m_state == State::Open)
            emit bytesReceived(bytes);
    };
    if (delayMs <= 0)
        QTimer::singleShot(0, this, std::move(arrive)); // queued, as a port's readyRead
    else
        after(delayMs, std::move(arrive));
}

void FakeTransport::after(int ms, std::function<void()> f)
{
    if (!m_scheduler) {
        QTimer::singleShot(ms, this, std::move(f));
        return;
    }
    m_scheduler(ms, [alive = QPointer<FakeTransport>(this), f = std::move(f)] {
        if (alive)
            f();
    });
}

void FakeTransport::inject(const QByteArray &bytes)
{
    deliver(bytes, 0);
}

void FakeTransport::unplug()
{
    if (m_state != State::Open)
        return;
    emit errorOccurred(TransportError{TransportError::Kind::Unplugged,
                                      QStringLiteral("The fake adapter was unplugged.")});
    setState(State::Disconnected);
}

void FakeTransport::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

} // namespace lk::bustest
