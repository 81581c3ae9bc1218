#pragma once

#include "RequestTracker.h"

#include <protocol/Request.h>
#include <protocol/Series.h>
#include <safety/MotionGuard.h>
#include <safety/SoftLimits.h>

#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// What became of a motion command handed to the gate.
struct MotionOutcome {
    bool sent = false;
    quint64 ticket = 0;
    QString refusal; ///< translated reason when nothing was sent
    safety::LimitKind limit = safety::LimitKind::None;
    std::optional<protocol::FieldError> fieldError; ///< the builder refused a value
};

/// The only way the drive views send a command that can move a motor: the builder's
/// verdict first (FieldError), then MotionGuard (series and soft limits), then the bus.
/// A refused command sends nothing and says which check stopped it.
class MotionGate {
public:
    static MotionOutcome submit(RequestTracker &tracker, const protocol::BuildResult &built,
                                std::optional<protocol::Series> series,
                                const safety::SoftLimits &limits,
                                RequestTracker::Callback callback = {});
};

} // namespace lk::ui
