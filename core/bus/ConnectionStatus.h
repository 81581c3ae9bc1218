#pragma once

#include "LinkMode.h"

#include <transport/CanBusCondition.h>
#include <transport/Transport.h>

#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace lk::bus {

/// The state of a session's link (BusSession::connectionChanged).
struct ConnectionStatus {
    transport::Transport::State state = transport::Transport::State::Closed;
    QString description; ///< the transport's description, e.g. "/dev/ttyUSB0 @ 115200"
    int baud = 0;
    QString reason; ///< why it closed or disconnected, when it did
    LinkMode mode = LinkMode::Active;
    /// The link is open and Active: the one capability every view that would transmit (a
    /// read on selection, a button, a poll) derives from. False while listening only.
    bool canTransmit = false;
    protocol::Link link = protocol::Link::Rs485; ///< what the transport carries
    /// CAN only: the bus as the controller sees it. Bus-off, error-passive and no-ACK are
    /// states of an open link (never "link lost"), worded with their fix in `conditionText`.
    transport::CanBusCondition canCondition = transport::CanBusCondition::Good;
    QString conditionText; ///< the sentence and fix of a bad canCondition; empty when good
    bool isOpen() const { return state == transport::Transport::State::Open; }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::ConnectionStatus)
