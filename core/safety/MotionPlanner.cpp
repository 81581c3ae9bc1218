#include "MotionPlanner.h"

#include <algorithm>
#include <cmath>

namespace lk::safety {

namespace {

using protocol::Command;

MotionPlan refused(LimitKind kind, double value, double limit, const protocol::Request &r,
                   std::optional<double> fromDeg = std::nullopt)
{
    MotionPlan p;
    p.verdict = Verdict{kind, value, limit, r.command, fromDeg, false};
    return p;
}

Command limitedForm(Command c)
{
    switch (c) {
    case Command::MultiPosition:
        return Command::MultiPositionLimited;
    case Command::SinglePosition:
        return Command::SinglePositionLimited;
    case Command::IncrementPosition:
        return Command::IncrementPositionLimited;
    default:
        return c;
    }
}

// The max speed field of a position payload (nullptr for any other payload).
std::optional<quint32> *maxSpeedOf(protocol::Request &r)
{
    if (auto *c = std::get_if<protocol::MultiPositionCommand>(&r.payload))
        return &c->maxSpeedRaw;
    if (auto *c = std::get_if<protocol::SinglePositionCommand>(&r.payload))
        return &c->maxSpeedRaw;
    if (auto *c = std::get_if<protocol::IncrementPositionCommand>(&r.payload))
        return &c->maxSpeedRaw;
    return nullptr;
}

double positiveMod(double v, double m)
{
    const double r = std::fmod(v, m);
    return r < 0 ? r + m : r;
}

// How far a single-turn move travels from multi-turn angle `fromDeg`: to the target angle
// within the turn, clockwise (+) or counter-clockwise (-), as the drive (and the simulator)
// do. The single-turn angle spans one output turn, `turnDeg` (0..36000 x ratio - 1 on a
// geared drive: ERRATA, docs/V2.35.md, docs/CAN.md), so a move may take up to ratio rotor turns.
double singleTurnTravelDeg(const protocol::SinglePositionCommand &c, double fromDeg, double turnDeg)
{
    const double current = positiveMod(fromDeg, turnDeg);
    const double target = positiveMod(c.angleRaw / 100.0, turnDeg); // divided: nearest double
    return c.direction == protocol::SpinDirection::Clockwise
               ? positiveMod(target - current, turnDeg)
               : -positiveMod(current - target, turnDeg);
}

// The one-output-turn and angle-window rules that need to know where the drive is.
std::optional<MotionPlan> checkDistance(const protocol::Request &r, const SoftLimits &limits,
                                        const DrivePosition &at)
{
    const double turn = at.outputTurnDeg();
    std::optional<double> target;
    if (const auto *c = std::get_if<protocol::MultiPositionCommand>(&r.payload)) {
        if (!at.angleDeg)
            return refused(LimitKind::AngleUnknown, 0, 0, r);
        // MotionGuard checks the target against the angle range.
        const double distance = std::fabs(static_cast<double>(c->angleRaw) / 100.0 - *at.angleDeg);
        if (distance > turn)
            return refused(LimitKind::OutputTurn, distance, turn, r, at.angleDeg);
    } else if (const auto *c = std::get_if<protocol::IncrementPositionCommand>(&r.payload)) {
        const double step = static_cast<double>(c->angleRaw) / 100.0;
        if (std::fabs(step) > turn)
            return refused(LimitKind::OutputTurn, std::fabs(step), turn, r);
        if (limits.minAngleDeg || limits.maxAngleDeg) {
            if (!at.angleDeg)
                return refused(LimitKind::AngleUnknown, 0, 0, r);
            target = *at.angleDeg + step;
        }
    } else if (const auto *c = std::get_if<protocol::SinglePositionCommand>(&r.payload)) {
        // Less than one output turn by construction; with an angle range set, where it ends
        // (from the angle within the turn, in the direction given) must lie inside it.
        if (limits.minAngleDeg || limits.maxAngleDeg) {
            if (!at.angleDeg)
                return refused(LimitKind::AngleUnknown, 0, 0, r);
            target = *at.angleDeg + singleTurnTravelDeg(*c, *at.angleDeg, turn);
        }
    }
    if (target) {
        const Verdict window = MotionGuard::checkTarget(*target, limits);
        if (!window.allowed())
            return refused(window.kind, window.value, window.limit, r);
    }
    return std::nullopt;
}

} // namespace

bool MotionPlanner::needsAngle(const protocol::Request &request, const SoftLimits &limits)
{
    if (std::holds_alternative<protocol::MultiPositionCommand>(request.payload))
        return true;
    const bool relative =
        std::holds_alternative<protocol::IncrementPositionCommand>(request.payload) ||
        std::holds_alternative<protocol::SinglePositionCommand>(request.payload);
    return relative && (limits.minAngleDeg || limits.maxAngleDeg);
}

bool MotionPlanner::isPosition(Command c)
{
    return c >= Command::MultiPosition && c <= Command::IncrementPositionLimited;
}

MotionPlan MotionPlanner::plan(const protocol::Request &request,
                               std::optional<protocol::Series> series, const SoftLimits &soft,
                               const DrivePosition &position, const DriveLimits &drive)
{
    MotionPlan p = planWithin(request, series, drive.narrow(soft), position);
    if (!p.allowed())
        p.verdict.drivesOwn = drive.decided(p.verdict, soft);
    else if (p.bound == SpeedBound::SoftLimit || p.bound == SpeedBound::Command)
        p.drivesOwnSpeed = drive.capsSpeed(soft);
    return p;
}

MotionPlan MotionPlanner::planWithin(const protocol::Request &request,
                                     std::optional<protocol::Series> series,
                                     const SoftLimits &limits, const DrivePosition &position)
{
    protocol::Request out = request;
    MotionPlan p;
    if (std::optional<quint32> *maxSpeed = maxSpeedOf(out); maxSpeed && isPosition(out.command)) {
        if (std::optional<MotionPlan> no = checkDistance(out, limits, position))
            return *no;
        const double top = MotionGuard::topSpeedDps(series);
        if (*maxSpeed) {
            p.bound = SpeedBound::UserMaxSpeed;
            p.boundDps = **maxSpeed * protocol::kCentiUnits;
        } else {
            // Never above the bound: round the cap down to the wire's 0.01 dps.
            p.bound = limits.maxSpeedDps > top ? SpeedBound::SeriesTop : SpeedBound::SoftLimit;
            const double cap = std::min(limits.maxSpeedDps, top);
            *maxSpeed = static_cast<quint32>(std::max(0.0, std::floor(cap * 100.0 + 1e-6)));
            p.boundDps = **maxSpeed * protocol::kCentiUnits;
            out.command = limitedForm(out.command);
            p.limited = true;
        }
    } else if (std::holds_alternative<protocol::SpeedCommand>(out.payload)) {
        p.bound = SpeedBound::Command;
        p.boundDps = limits.maxSpeedDps;
    }
    p.verdict = MotionGuard::check(out, series, limits);
    if (!p.verdict.allowed()) {
        p.bound = SpeedBound::None;
        return p;
    }
    p.request = out;
    return p;
}

} // namespace lk::safety
