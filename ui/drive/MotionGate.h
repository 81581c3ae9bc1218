#pragma once

#include "RequestTracker.h"

#include <protocol/Request.h>
#include <protocol/Series.h>
#include <safety/MotionGuard.h>
#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// What became of a motion command handed to the gate.
struct MotionOutcome {
    bool sent = false;
    quint64 ticket = 0;
    bool pending = false; ///< waits for the drive's angle (0x92) before it is planned and sent
    QString refusal;      ///< translated reason when nothing was sent
    QString bound;        ///< which speed bound applied (VerdictText::speedBound), when sent
    std::optional<protocol::Request> request; ///< what was sent (a position move: its limited form)
    safety::LimitKind limit = safety::LimitKind::None;
    std::optional<protocol::FieldError> fieldError; ///< the builder refused a value
};

/// The only way the drive views send a command that can move a motor: the builder's
/// verdict first (FieldError), then safety::MotionPlanner (speed bound on every move, targets
/// checked from the drive's angle, series and soft limits, each lowered to the drive's own
/// limit where one was read), then the bus. A refused command sends nothing and says which
/// check stopped it, naming a limit of the drive's own as such.
class MotionGate {
public:
    static MotionOutcome submit(RequestTracker &tracker, const protocol::BuildResult &built,
                                std::optional<protocol::Series> series,
                                const safety::SoftLimits &limits,
                                const safety::DrivePosition &position,
                                RequestTracker::Callback callback = {},
                                const safety::DriveLimits &drive = {});
};

} // namespace lk::ui
