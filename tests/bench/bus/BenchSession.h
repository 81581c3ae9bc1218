#pragma once

// Opening a BusSession on a serial device the way lkctl and lkstudio do, for the benchmarks
// that drive lksim over its pseudo-terminal.

#include "BenchUtil.h"

#include <bus/BusSession.h>
#include <transport/SerialTransport.h>

namespace lk::bench {

/// Opens `session` on `device` at `baud` (8N1, SerialTransport); false when it is not open
/// within 10 s.
inline bool openSerial(bus::BusSession &session, const QString &device, int baud)
{
    transport::SerialSettings s;
    s.portName = device;
    s.baud = baud;
    session.open(transport::SerialTransport::factory(s), baud);
    return waitUntil([&] { return session.connection().isOpen(); }, 10000);
}

} // namespace lk::bench
