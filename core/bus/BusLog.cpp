#include "BusLog.h"

namespace lk::bus {
// Debug messages (one per scan pass...) only when asked: QT_LOGGING_RULES="lk.bus.debug=true".
Q_LOGGING_CATEGORY(lcBus, "lk.bus", QtInfoMsg)
} // namespace lk::bus
