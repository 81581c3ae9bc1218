#include "MotionGate.h"

#include "DriveText.h"

#include <text/VerdictText.h>

namespace lk::ui {

MotionOutcome MotionGate::submit(RequestTracker &tracker, const protocol::BuildResult &built,
                                 std::optional<protocol::Series> series,
                                 const safety::SoftLimits &limits,
                                 const safety::DrivePosition &position,
                                 RequestTracker::Callback callback,
                                 const safety::DriveLimits &drive)
{
    MotionOutcome out;
    if (!built.ok()) {
        out.fieldError = built.error;
        out.refusal = DriveText::fieldError(built.error);
        return out;
    }
    const safety::MotionPlan plan =
        safety::MotionPlanner::plan(*built.request, series, limits, position, drive);
    if (!plan.allowed()) {
        out.limit = plan.verdict.kind;
        out.refusal = DriveText::refusal(plan.verdict, series);
        return out;
    }
    const protocol::Request &request = *plan.request;
    // A relative move repeated after a lost reply would move twice: never retry it.
    const bool relative = request.command == protocol::Command::IncrementPosition ||
                          request.command == protocol::Command::IncrementPositionLimited;
    out.ticket =
        tracker.send(request, std::move(callback), bus::Priority::Operator, relative ? 0 : -1);
    out.sent = out.ticket != 0;
    if (out.sent) {
        out.request = request;
        out.bound = plan.drivesOwnSpeed ? safety::DriveLimits::speedBound(plan.bound, plan.boundDps)
                                        : text::VerdictText::speedBound(plan.bound, plan.boundDps);
    }
    if (!out.sent)
        out.refusal = QCoreApplication::translate("lk::ui::MotionGate", "Not connected.");
    return out;
}

} // namespace lk::ui
