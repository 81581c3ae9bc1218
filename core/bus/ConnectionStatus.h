#pragma once

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
    bool isOpen() const { return state == transport::Transport::State::Open; }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::ConnectionStatus)
