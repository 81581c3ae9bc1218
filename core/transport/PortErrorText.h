#pragma once

#include "Transport.h"

#include <QtCore/QString>

namespace lk::transport {

/// A TransportError for a serial port, with a message a technician can act on:
/// `port` is the device path, `baud` matters for BadSettings, `detail` is the driver's own
/// words (or the list of ports found, for NoSuchPort) and is appended when not empty.
TransportError portError(TransportError::Kind kind, const QString &port, int baud = 0,
                         const QString &detail = {});

} // namespace lk::transport
