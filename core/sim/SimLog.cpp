#include "SimLog.h"

namespace lk::sim {
Q_LOGGING_CATEGORY(lcSim, "lk.sim")
}
