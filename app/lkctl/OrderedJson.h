#pragma once

#include <protocol/OrderedJson.h>

namespace lk::lkctl {

// The writer lives in core/protocol beside the field table that orders its keys; lkctl's
// commands (and MonitorTable, owned elsewhere) keep their spelling.
using OrderedJson = protocol::OrderedJson;

} // namespace lk::lkctl
