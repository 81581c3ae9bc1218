#include "MotionGuard.h"

#include <QtCore/QCoreApplication>

#include <motor/SeriesLimits.h>

#include <algorithm>
#include <cmath>

namespace lk::safety {

namespace {

using protocol::Command;
using protocol::Series;

Verdict refuse(LimitKind kind, double value, double limit, const QString &message)
{
    return Verdict{kind, value, limit, message};
}

Verdict checkSpeed(double dps, std::optional<Series> series, const SoftLimits &limits,
                   const char *what)
{
    const double top = MotionGuard::topSpeedDps(series);
    const double v = std::fabs(dps);
    if (v > top) {
        // Whole sentences for the known and the unknown series: a translation cannot be glued
        // together from "the" + "slowest" + "series".
        const QString whatText = QCoreApplication::translate("lk::safety::MotionGuard", what);
        const QString message =
            series
                ? QCoreApplication::translate("lk::safety::MotionGuard",
                                              "%1 %2 dps exceeds the %3 series top speed of %4 dps")
                      .arg(whatText)
                      .arg(v)
                      .arg(protocol::seriesName(*series))
                      .arg(top)
                : QCoreApplication::translate("lk::safety::MotionGuard",
                                              "%1 %2 dps exceeds %3 dps, the top speed of the "
                                              "slowest series (the drive's series is unknown)")
                      .arg(whatText)
                      .arg(v)
                      .arg(top);
        return refuse(LimitKind::SeriesSpeed, v, top, message);
    }
    // A speed limit always exists (SoftLimits): none at all is refused, never read as "any".
    if (!(limits.maxSpeedDps > 0))
        return refuse(LimitKind::SoftSpeed, v, 0,
                      QCoreApplication::translate("lk::safety::MotionGuard",
                                                  "no speed limit is set: set one first"));
    if (v > limits.maxSpeedDps)
        return refuse(LimitKind::SoftSpeed, v, limits.maxSpeedDps,
                      QCoreApplication::translate("lk::safety::MotionGuard",
                                                  "%1 %2 dps exceeds your speed limit of %3 dps")
                          .arg(QCoreApplication::translate("lk::safety::MotionGuard", what))
                          .arg(v)
                          .arg(limits.maxSpeedDps));
    return {};
}

Verdict checkMaxSpeed(const std::optional<quint32> &raw, std::optional<Series> series,
                      const SoftLimits &limits)
{
    if (!raw)
        return {};
    return checkSpeed(*raw * protocol::kCentiUnits, series, limits,
                      QT_TRANSLATE_NOOP("lk::safety::MotionGuard", "max speed"));
}

Verdict checkTorque(double iqA, std::optional<Series> series, const SoftLimits &limits)
{
    if (!series)
        return refuse(
            LimitKind::UnknownSeries, 0, 0,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "torque needs the drive's series: scan the bus first"));
    const double v = std::fabs(iqA);
    const double rated = motor::seriesLimits(*series).maxCurrentA;
    if (v > rated)
        return refuse(
            LimitKind::SeriesCurrent, v, rated,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "torque current %1 A exceeds the %2 series rating of %3 A")
                .arg(v)
                .arg(protocol::seriesName(*series))
                .arg(rated));
    if (v > limits.maxTorqueA)
        return refuse(
            LimitKind::SoftTorque, v, limits.maxTorqueA,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "torque current %1 A exceeds your torque limit of %2 A")
                .arg(v)
                .arg(limits.maxTorqueA));
    return {};
}

Verdict checkMultiTurn(const protocol::MultiPositionCommand &c, std::optional<Series> series,
                       const SoftLimits &limits)
{
    const Verdict window =
        MotionGuard::checkTarget(static_cast<double>(c.angleRaw) * protocol::kCentiUnits, limits);
    if (!window.allowed())
        return window;
    return checkMaxSpeed(c.maxSpeedRaw, series, limits);
}

Verdict checkIncrement(const protocol::IncrementPositionCommand &c, std::optional<Series> series,
                       const SoftLimits &limits)
{
    const double deg = std::fabs(c.angleRaw * protocol::kCentiUnits);
    if (limits.maxIncrementDeg && deg > *limits.maxIncrementDeg)
        return refuse(
            LimitKind::SoftIncrement, deg, *limits.maxIncrementDeg,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "increment of %1 deg exceeds your step limit of %2 deg")
                .arg(deg)
                .arg(*limits.maxIncrementDeg));
    return checkMaxSpeed(c.maxSpeedRaw, series, limits);
}

} // namespace

Verdict MotionGuard::checkTarget(double deg, const SoftLimits &limits)
{
    if (limits.minAngleDeg && deg < *limits.minAngleDeg)
        return refuse(
            LimitKind::AngleBelowMin, deg, *limits.minAngleDeg,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "target %1 deg is below your angle range (min %2 deg)")
                .arg(deg)
                .arg(*limits.minAngleDeg));
    if (limits.maxAngleDeg && deg > *limits.maxAngleDeg)
        return refuse(
            LimitKind::AngleAboveMax, deg, *limits.maxAngleDeg,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "target %1 deg is above your angle range (max %2 deg)")
                .arg(deg)
                .arg(*limits.maxAngleDeg));
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
    const Command cmd = request.command;
    if (!protocol::CommandTable::info(cmd).movesMotor)
        return {};
    if (cmd == Command::OpenLoop && !series)
        return refuse(
            LimitKind::UnknownSeries, 0, 0,
            QCoreApplication::translate("lk::safety::MotionGuard",
                                        "open loop needs the drive's series: scan the bus first"));
    if (series && !motor::supports(*series, cmd))
        return refuse(
            LimitKind::Unsupported, 0, 0,
            QCoreApplication::translate("lk::safety::MotionGuard", "%1 drives do not implement %2")
                .arg(protocol::seriesName(*series), protocol::CommandTable::name(cmd)));
    const auto &p = request.payload;
    if (const auto *c = std::get_if<protocol::OpenLoopCommand>(&p)) {
        const int v = std::abs(int(c->power));
        if (v > limits.maxPower)
            return refuse(
                LimitKind::SoftPower, v, limits.maxPower,
                QCoreApplication::translate("lk::safety::MotionGuard",
                                            "open-loop power %1 exceeds your power limit of %2")
                    .arg(v)
                    .arg(limits.maxPower));
        return {};
    }
    if (const auto *c = std::get_if<protocol::TorqueCommand>(&p))
        return checkTorque(c->iqA(), series, limits);
    if (const auto *c = std::get_if<protocol::SpeedCommand>(&p))
        return checkSpeed(c->speedDps(), series, limits,
                          QT_TRANSLATE_NOOP("lk::safety::MotionGuard", "speed"));
    if (const auto *c = std::get_if<protocol::MultiPositionCommand>(&p))
        return checkMultiTurn(*c, series, limits);
    if (const auto *c = std::get_if<protocol::SinglePositionCommand>(&p))
        return checkMaxSpeed(c->maxSpeedRaw, series, limits);
    if (const auto *c = std::get_if<protocol::IncrementPositionCommand>(&p))
        return checkIncrement(*c, series, limits);
    return {}; // motor_run resumes a command that passed this gate when it was sent
}

} // namespace lk::safety
