#include "BusLog.h"

namespace lk::bus {
Q_LOGGING_CATEGORY(lcBus, "lk.bus")
} // namespace lk::bus
