#pragma once

#include <QtCore/QLoggingCategory>

namespace lk::bus {
Q_DECLARE_LOGGING_CATEGORY(lcBus)
} // namespace lk::bus
