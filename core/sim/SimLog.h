#pragma once

#include <QtCore/QLoggingCategory>

namespace lk::sim {
Q_DECLARE_LOGGING_CATEGORY(lcSim) ///< "lk.sim": simulator diagnostics (ROM files, faults)
}
