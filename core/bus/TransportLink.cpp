#include "TransportLink.h"

#include <transport/CanTransport.h>

namespace lk::bus {

using transport::Transport;

TransportLink::TransportLink(TransportFactory factory, int baud, QObject *parent)
    : QObject(parent), m_factory(std::move(factory)), m_baud(baud)
{
    m_reported.baud = baud;
}

TransportLink::~TransportLink()
{
    drop();
}

bool TransportLink::start()
{
    attach(m_factory ? m_factory(m_baud) : nullptr);
    return open();
}

bool TransportLink::reopen()
{
    if (!m_transport)
        attach(m_factory ? m_factory(m_baud) : nullptr);
    return open();
}

bool TransportLink::reopenAt(int baud)
{
    m_baud = baud;
    attach(m_factory ? m_factory(baud) : nullptr);
    return open();
}

void TransportLink::close(const QString &reason)
{
    drop();
    m_reported.state = Transport::State::Closed;
    m_reported.reason = reason;
    m_reported.canTransmit = false;
    emit connectionChanged(m_reported);
}

void TransportLink::attach(std::unique_ptr<Transport> t)
{
    drop();
    m_transport = std::move(t);
    if (!m_transport)
        return;
    m_transport->setReadOnly(m_mode == LinkMode::ListenOnly);
    m_link = m_transport->link();
    m_condition = transport::CanBusCondition::Good;
    m_conditionText.clear();
    // Good and Warning come as a condition alone; the bad ones come with their sentence as an
    // error first (onTransportError). Through the base signal, so a recorder in between passes
    // them on.
    connect(m_transport.get(), &Transport::canConditionChanged, this,
            [this](transport::CanBusCondition c) {
                if (c == transport::CanBusCondition::Good ||
                    c == transport::CanBusCondition::Warning)
                    onCanCondition(c, {});
            });
    connect(m_transport.get(), &Transport::bytesReceived, this, &TransportLink::bytesReceived);
    connect(m_transport.get(), &Transport::stateChanged, this, &TransportLink::onTransportState);
    connect(m_transport.get(), &Transport::errorOccurred, this, &TransportLink::onTransportError);
}

void TransportLink::drop()
{
    if (!m_transport)
        return;
    // Silence it first: closing on purpose is not a disconnect to report or to fail on.
    disconnect(m_transport.get(), nullptr, this, nullptr);
    m_transport->close();
    m_transport.reset();
}

bool TransportLink::open()
{
    if (!m_transport) {
        m_lastError = tr("No transport: the transport factory returned nothing.");
        report(m_lastError);
        return false;
    }
    m_lastError.clear();
    const bool ok = m_transport->state() == Transport::State::Open || m_transport->open();
    if (ok)
        onTransportState(Transport::State::Open);
    else
        report(m_lastError);
    return ok;
}

void TransportLink::write(const QByteArray &bytes)
{
    if (m_mode == LinkMode::ListenOnly) {
        m_refusedBytes += static_cast<quint64>(bytes.size());
        return;
    }
    if (m_transport)
        m_transport->write(bytes);
}

Transport::State TransportLink::state() const
{
    return m_transport ? m_transport->state() : Transport::State::Closed;
}

int TransportLink::baud() const
{
    return m_transport ? m_transport->baud() : m_baud;
}

void TransportLink::onCanCondition(transport::CanBusCondition condition, const QString &text)
{
    m_condition = condition;
    m_conditionText = text;
    report();
}

void TransportLink::onTransportError(const transport::TransportError &error)
{
    using Kind = transport::TransportError::Kind;
    // A bad CAN bus is a state of the open link with its fix, not a failure of the link.
    if (error.kind == Kind::CanBusOff || error.kind == Kind::CanErrorPassive ||
        error.kind == Kind::CanNoAcknowledge) {
        onCanCondition(error.kind == Kind::CanBusOff ? transport::CanBusCondition::BusOff
                       : error.kind == Kind::CanErrorPassive
                           ? transport::CanBusCondition::ErrorPassive
                           : transport::CanBusCondition::NoAcknowledge,
                       error.message);
        emit errorOccurred(error);
        return;
    }
    m_lastError = error.message;
    // An unplug is a state, not an error: its words are the reason of the Disconnected state
    // that follows, and that state is its one report (banner, log, traffic).
    if (error.kind == transport::TransportError::Kind::Unplugged)
        return;
    emit errorOccurred(error);
}

void TransportLink::onTransportState(Transport::State state)
{
    if (state == Transport::State::Open) {
        emit stateChanged(state, {});
        return;
    }
    const QString reason =
        m_lastError.isEmpty()
            ? (state == Transport::State::Closed ? tr("closed") : tr("disconnected"))
            : m_lastError;
    emit stateChanged(state, reason);
}

void TransportLink::report(const QString &reason)
{
    ConnectionStatus s;
    s.state = state();
    s.description = m_transport ? m_transport->description() : QString();
    s.baud = baud();
    s.reason = s.state == Transport::State::Open ? QString() : reason;
    s.mode = m_mode;
    s.canTransmit = s.isOpen() && m_mode == LinkMode::Active;
    s.link = link();
    s.canCondition = m_condition;
    s.conditionText = m_conditionText;
    if (s.state == m_reported.state && s.description == m_reported.description &&
        s.baud == m_reported.baud && s.reason == m_reported.reason && s.mode == m_reported.mode &&
        s.link == m_reported.link && s.canCondition == m_reported.canCondition)
        return;
    m_reported = s;
    emit connectionChanged(s);
}

} // namespace lk::bus
