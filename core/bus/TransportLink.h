#pragma once

#include "ConnectionStatus.h"
#include "LinkMode.h"
#include "LinkTiming.h"
#include "TransportFactory.h"

#include <transport/Transport.h>

#include <QtCore/QObject>

#include <memory>

namespace lk::bus {

/// The transport of one bus and its lifecycle, on the bus thread: makes it with the factory
/// (at a baud), opens it, opens it again after a disconnect, replaces it by one at another
/// baud, and closes it on purpose without that counting as a disconnect. It words why the link
/// is not open (the transport's last error, else "closed" / "disconnected") and reports each
/// change of ConnectionStatus once. An unplug is such a change, not an error: errorOccurred
/// carries only failures (an open that failed, an I/O error). What a change means for the requests
/// is its owner's business (BusWorker): stateChanged comes first, the owner reacts, then calls
/// report().
class TransportLink : public QObject {
    Q_OBJECT
public:
    TransportLink(TransportFactory factory, int baud, QObject *parent = nullptr);
    ~TransportLink() override;

    /// Makes a new transport at the current baud (replacing one there is) and opens it.
    bool start();
    /// Opens the transport there is, making one first if there is none (after a failed
    /// start, say). True when it is open.
    bool reopen();
    /// Replaces the transport by a new one from the factory at `baud` and opens it.
    bool reopenAt(int baud);
    /// Closes and deletes the transport without reporting a disconnect, then reports the link
    /// Closed for `reason` (always, even when it was already).
    void close(const QString &reason);

    /// Listen-only or active. Each transport made from here on is read-only in ListenOnly
    /// (Transport::setReadOnly); the one there is keeps how it was opened until replaced.
    void setMode(LinkMode mode) { m_mode = mode; }
    LinkMode mode() const { return m_mode; }
    /// Hands bytes to the transport (none, closed or disconnected: dropped). In ListenOnly it
    /// drops them and counts them in refusedBytes(): the bus's last guard, never reached
    /// when every sender asks BusWorker first.
    void write(const QByteArray &bytes);
    quint64 refusedBytes() const { return m_refusedBytes; }
    transport::Transport::State state() const;
    /// The transport's baud, or the baud the next one is made at.
    int baud() const;
    /// What the transport carries (RS485 bytes or CAN records); the last transport's link
    /// while there is none.
    protocol::Link link() const { return m_transport ? m_transport->link() : m_link; }
    /// The link's timing at its bit rate: what timeouts, quiet periods and limits count.
    LinkTiming timing() const { return LinkTiming::of(link(), baud()); }
    /// The transport's last error since the last open attempt (empty: none).
    QString lastError() const { return m_lastError; }

    /// Emits connectionChanged with the link as it is now, when that differs from the last
    /// report; `reason` says why it is not open.
    void report(const QString &reason = {});

signals:
    void bytesReceived(const QByteArray &bytes);
    /// The link opened, closed or dropped; `reason` says why when it is not open. Not
    /// emitted for close() nor for the transport a start() or reopenAt() replaces.
    void stateChanged(lk::transport::Transport::State state, const QString &reason);
    /// A failure of the transport; never an unplug (TransportError::Kind::Unplugged).
    void errorOccurred(const lk::transport::TransportError &error);
    void connectionChanged(const lk::bus::ConnectionStatus &status);

private:
    bool open();
    void attach(std::unique_ptr<transport::Transport> t);
    void drop();
    void onTransportState(transport::Transport::State state);
    void onTransportError(const transport::TransportError &error);
    /// A CAN transport's bus condition changed: a state of the open link, reported.
    void onCanCondition(transport::CanBusCondition condition, const QString &text);

    TransportFactory m_factory;
    int m_baud;
    std::unique_ptr<transport::Transport> m_transport;
    LinkMode m_mode = LinkMode::Active;
    quint64 m_refusedBytes = 0;
    protocol::Link m_link = protocol::Link::Rs485;
    transport::CanBusCondition m_condition = transport::CanBusCondition::Good;
    QString m_conditionText;
    ConnectionStatus m_reported;
    QString m_lastError;
};

} // namespace lk::bus
