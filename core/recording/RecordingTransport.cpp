#include "RecordingTransport.h"

namespace lk::recording {

using transport::Transport;

RecordingTransport::RecordingTransport(std::unique_ptr<Transport> inner,
                                       std::shared_ptr<RecordSink> sink,
                                       std::shared_ptr<bus::BusClock> clock, QObject *parent)
    : Transport(parent), m_inner(std::move(inner)), m_sink(std::move(sink)),
      m_clock(std::move(clock))
{
    connect(m_inner.get(), &Transport::bytesReceived, this, [this](const QByteArray &bytes) {
        m_sink->append(RecordEvent::data(RecordEvent::Kind::Rx, m_clock->nowNs(), bytes));
        emit bytesReceived(bytes);
    });
    connect(m_inner.get(), &Transport::stateChanged, this, [this](State s) {
        if (s == State::Disconnected)
            recordLink(LinkEventKind::Disconnected, m_inner->description());
        emit stateChanged(s);
    });
    connect(m_inner.get(), &Transport::errorOccurred, this,
            [this](const transport::TransportError &error) {
                recordLink(LinkEventKind::Error, error.message);
                emit errorOccurred(error);
            });
    connect(m_inner.get(), &Transport::canConditionChanged, this, &Transport::canConditionChanged);
}

RecordingTransport::~RecordingTransport()
{
    // The inner transport goes first, while this object can still forward its last signals.
    m_inner.reset();
}

void RecordingTransport::recordLink(LinkEventKind kind, const QString &text)
{
    RecordEvent e;
    e.kind = RecordEvent::Kind::Link;
    e.timeNs = m_clock->nowNs();
    e.link = kind;
    e.baud = m_inner->baud();
    e.text = text;
    m_sink->append(std::move(e));
}

bool RecordingTransport::open()
{
    // Listen-only reaches the transport that owns the port: it opens read-only and refuses.
    m_inner->setReadOnly(isReadOnly());
    const bool ok = m_inner->open();
    if (ok)
        recordLink(LinkEventKind::Opened, m_inner->description());
    return ok;
}

void RecordingTransport::close()
{
    if (m_inner->state() == State::Open)
        recordLink(LinkEventKind::Closed, m_inner->description());
    m_inner->close();
}

void RecordingTransport::write(const QByteArray &bytes)
{
    if (refuseWriteIfReadOnly(bytes))
        return; // never recorded as sent: nothing was
    // Only what can reach the wire: a closed or disconnected transport drops the bytes.
    if (m_inner->state() == State::Open)
        m_sink->append(RecordEvent::data(RecordEvent::Kind::Tx, m_clock->nowNs(), bytes));
    m_inner->write(bytes);
}

bus::TransportFactory recordingFactory(bus::TransportFactory inner,
                                       std::shared_ptr<RecordSink> sink,
                                       std::shared_ptr<bus::BusClock> clock)
{
    auto lastBaud = std::make_shared<int>(0);
    return [inner = std::move(inner), sink = std::move(sink), clock = std::move(clock),
            lastBaud](int baud) -> std::unique_ptr<Transport> {
        std::unique_ptr<Transport> made = inner(baud);
        if (!made)
            return nullptr;
        if (*lastBaud != 0 && *lastBaud != baud) {
            RecordEvent e;
            e.kind = RecordEvent::Kind::Link;
            e.timeNs = clock->nowNs();
            e.link = LinkEventKind::BaudChanged;
            e.baud = baud;
            e.text = made->description();
            sink->append(std::move(e));
        }
        *lastBaud = baud;
        return std::make_unique<RecordingTransport>(std::move(made), sink, clock);
    };
}

} // namespace lk::recording
