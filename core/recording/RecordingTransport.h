#pragma once

#include "RecordSink.h"

#include <bus/BusClock.h>
#include <bus/TransportFactory.h>
#include <transport/Transport.h>

#include <memory>

namespace lk::recording {

/// A Transport that passes everything through to another and hands a copy of each tx and rx
/// chunk, state change and error to a RecordSink, stamped with the session clock. It changes
/// nothing the bus engine sees (the link it carries, listen-only included); the sink does the
/// disk work elsewhere.
class RecordingTransport : public transport::Transport {
    Q_OBJECT
public:
    RecordingTransport(std::unique_ptr<transport::Transport> inner,
                       std::shared_ptr<RecordSink> sink, std::shared_ptr<bus::BusClock> clock,
                       QObject *parent = nullptr);
    ~RecordingTransport() override;

    bool open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    State state() const override { return m_inner->state(); }
    int baud() const override { return m_inner->baud(); }
    QString description() const override { return m_inner->description(); }
    /// The wrapped transport's: a recorded CAN link is still CAN to the engine.
    protocol::Link link() const override { return m_inner->link(); }

    transport::Transport *inner() const { return m_inner.get(); }

private:
    void recordLink(LinkEventKind kind, const QString &text);

    std::unique_ptr<transport::Transport> m_inner;
    std::shared_ptr<RecordSink> m_sink;
    std::shared_ptr<bus::BusClock> m_clock;
};

/// Wraps a factory so that every transport it makes (one per baud of a sweep, too) records
/// into the same sink on the same clock; a reopen at another baud is recorded as BaudChanged.
bus::TransportFactory recordingFactory(bus::TransportFactory inner,
                                       std::shared_ptr<RecordSink> sink,
                                       std::shared_ptr<bus::BusClock> clock);

} // namespace lk::recording
