#pragma once

#include <transport/Transport.h>

#include <functional>
#include <memory>

namespace lk::bus {

/// Makes the transport of a session. BusSession runs it on the bus thread (the transport
/// must be created in the thread that uses it), once at open() and again for each baud of
/// a baud sweep. The argument is the baud to open at.
using TransportFactory = std::function<std::unique_ptr<transport::Transport>(int baud)>;

} // namespace lk::bus
