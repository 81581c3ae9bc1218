#include "MotionGuard.h"

#include <motor/SeriesLimits.h>

#include <algorithm>
#include <cmath>

namespace lk::safety {

namespace {

using protocol::Command;
using protocol::Series;

Verdict refuse(LimitKind kind, double value, double limit)
{
    return Verdict{kind, value, limit, std::nullopt, std::nullopt, false};
}

Verdict checkSpeed(double dps, std::optional<Series> series, const SoftLimits &limits)
{
    const double top = MotionGuard::topSpeedDps(series);
    const double v = std::fabs(dps);
    if (v > top)
        return refuse(LimitKind::SeriesSpeed, v, top);
    // A speed limit always exists (SoftLimits): none at all (limit 0) is refused, never read
    // as "any".
    if (!(limits.maxSpeedDps > 0))
        return refuse(LimitKind::SoftSpeed, v, 0);
    if (v > limits.maxSpeedDps)
        return refuse(LimitKind::SoftSpeed, v, limits.maxSpeedDps);
    return {};
}

Verdict checkMaxSpeed(const std::optional<quint32> &raw, std::optional<Series> series,
                      const SoftLimits &limits)
{
    if (!raw)
        return {};
    // Divided, not multiplied by 0.01: the division rounds to the double nearest the decimal
    // value, the one the limit was parsed as (36090 x 0.01 is 360.90000000000003, over a
    // limit of 360.9 that MotionPlanner sent as exactly 36090).
    return checkSpeed(*raw / 100.0, series, limits);
}

Verdict checkTorque(double iqA, std::optional<Series> series, const SoftLimits &limits)
{
    if (!series)
        return refuse(LimitKind::UnknownSeries, 0, 0);
    const double v = std::fabs(iqA);
    const double rated = motor::seriesLimits(*series).maxCurrentA;
    if (v > rated)
        return refuse(LimitKind::SeriesCurrent, v, rated);
    if (v > limits.maxTorqueA)
        return refuse(LimitKind::SoftTorque, v, limits.maxTorqueA);
    return {};
}

Verdict checkMultiTurn(const protocol::MultiPositionCommand &c, std::optional<Series> series,
                       const SoftLimits &limits)
{
    // Divided, as checkMaxSpeed does: 36090 x 0.01 is 360.90000000000003, over a limit of
    // 360.9 the target was built from; 36090 / 100.0 is the double nearest 360.9.
    const Verdict window =
        MotionGuard::checkTarget(static_cast<double>(c.angleRaw) / 100.0, limits);
    if (!window.allowed())
        return window;
    return checkMaxSpeed(c.maxSpeedRaw, series, limits);
}

Verdict checkIncrement(const protocol::IncrementPositionCommand &c, std::optional<Series> series,
                       const SoftLimits &limits)
{
    const double deg = std::fabs(static_cast<double>(c.angleRaw) / 100.0); // as checkMultiTurn
    if (limits.maxIncrementDeg && deg > *limits.maxIncrementDeg)
        return refuse(LimitKind::SoftIncrement, deg, *limits.maxIncrementDeg);
    return checkMaxSpeed(c.maxSpeedRaw, series, limits);
}

Verdict checkRequest(const protocol::Request &request, std::optional<Series> series,
                     const SoftLimits &limits)
{
    const Command cmd = request.command;
    if (!protocol::CommandTable::info(cmd).movesMotor)
        return {};
    if (cmd == Command::OpenLoop && !series)
        return refuse(LimitKind::UnknownSeries, 0, 0);
    if (series && !motor::supports(*series, cmd))
        return refuse(LimitKind::Unsupported, 0, 0);
    const auto &p = request.payload;
    if (const auto *c = std::get_if<protocol::OpenLoopCommand>(&p)) {
        const int v = std::abs(int(c->power));
        if (v > limits.maxPower)
            return refuse(LimitKind::SoftPower, v, limits.maxPower);
        return {};
    }
    if (const auto *c = std::get_if<protocol::TorqueCommand>(&p))
        return checkTorque(c->iqA(), series, limits);
    if (const auto *c = std::get_if<protocol::SpeedCommand>(&p))
        return checkSpeed(c->speedDps(), series, limits);
    if (const auto *c = std::get_if<protocol::MultiPositionCommand>(&p))
        return checkMultiTurn(*c, series, limits);
    if (const auto *c = std::get_if<protocol::SinglePositionCommand>(&p))
        return checkMaxSpeed(c->maxSpeedRaw, series, limits);
    if (const auto *c = std::get_if<protocol::IncrementPositionCommand>(&p))
        return checkIncrement(*c, series, limits);
    return {}; // motor_run resumes a command that passed this gate when it was sent
}

} // namespace

Verdict MotionGuard::checkTarget(double deg, const SoftLimits &limits)
{
    if (limits.minAngleDeg && deg < *limits.minAngleDeg)
        return refuse(LimitKind::AngleBelowMin, deg, *limits.minAngleDeg);
    if (limits.maxAngleDeg && deg > *limits.maxAngleDeg)
        return refuse(LimitKind::AngleAboveMax, deg, *limits.maxAngleDeg);
    return {};
}

double MotionGuard::topSpeedDps(std::optional<Series> series)
{
    if (series)
        return motor::seriesLimits(*series).maxSpeedDps();
    double lowest = motor::seriesLimits(Series::MS).maxSpeedDps();
    for (Series s : {Series::MF, Series::MG, Series::MH})
        lowest = std::min(lowest, motor::seriesLimits(s).maxSpeedDps());
    return lowest;
}

Verdict MotionGuard::check(const protocol::Request &request, std::optional<Series> series,
                           const SoftLimits &limits)
{
    Verdict v = checkRequest(request, series, limits);
    if (!v.allowed())
        v.command = request.command;
    return v;
}

} // namespace lk::safety
