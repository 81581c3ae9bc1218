#pragma once

namespace lk::bus {

/// Register the bus value types for queued connections. BusSession calls it; idempotent and
/// thread-safe, so tests and other users may call it too.
void registerBusMetaTypes();

} // namespace lk::bus
