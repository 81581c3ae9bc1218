#include "StepTestPlan.h"

#include <protocol/RequestBuilder.h>

#include <cmath>

namespace lk::tuning {

namespace {

using Role = StepSetpoint::Role;

QString unit(StepLoop loop)
{
    return loop == StepLoop::Speed ? QStringLiteral("dps") : QStringLiteral("deg");
}

// The setpoints' times and targets, before any is turned into a request.
QVector<StepSetpoint> timeline(const StepTestSpec &spec, double *endS)
{
    QVector<StepSetpoint> out;
    out.append({Role::PreRoll, 0, spec.from, spec.from, {}});
    const int edges = spec.periods == 1 ? 1 : 2 * spec.periods;
    for (int k = 0; k < edges; ++k) {
        const bool up = k % 2 == 0;
        out.append({Role::Edge,
                    spec.preRollS + k * spec.durationS,
                    up ? spec.to : spec.from,
                    up ? spec.from : spec.to,
                    {}});
    }
    *endS = spec.preRollS + edges * spec.durationS;
    // A single speed step would leave the drive at TO: it goes back to FROM as the test ends.
    if (spec.loop == StepLoop::Speed && edges == 1)
        out.append({Role::Return, *endS, spec.from, spec.to, {}});
    return out;
}

protocol::BuildResult build(const StepTestSpec &spec, double target)
{
    if (spec.loop == StepLoop::Speed)
        return protocol::build::speed(spec.id, target);
    // Without a max speed MotionPlanner makes 0xA3 its limited form at the speed limit.
    return spec.maxSpeedDps ? protocol::build::multiPosition(spec.id, target, *spec.maxSpeedDps)
                            : protocol::build::multiPosition(spec.id, target);
}

} // namespace

protocol::Command StepTestPlan::commandOf(StepLoop loop)
{
    return loop == StepLoop::Speed ? protocol::Command::Speed
                                   : protocol::Command::MultiPositionLimited;
}

QString StepTestPlan::checkSpec(const StepTestSpec &spec)
{
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(spec.from) || !finite(spec.to))
        return QStringLiteral("FROM and TO must be numbers");
    if (spec.from == spec.to)
        return QStringLiteral("FROM and TO are the same (%1 %2): there is no step")
            .arg(spec.from)
            .arg(unit(spec.loop));
    if (!finite(spec.durationS) || spec.durationS < StepTestSpec::kMinDurationS ||
        spec.durationS > StepTestSpec::kMaxDurationS)
        return QStringLiteral("the duration must be %1..%2 s, got %3")
            .arg(StepTestSpec::kMinDurationS)
            .arg(StepTestSpec::kMaxDurationS)
            .arg(spec.durationS);
    if (!finite(spec.preRollS) || spec.preRollS < StepTestSpec::kMinDurationS ||
        spec.preRollS > StepTestSpec::kMaxDurationS)
        return QStringLiteral("the pre-roll must be %1..%2 s, got %3")
            .arg(StepTestSpec::kMinDurationS)
            .arg(StepTestSpec::kMaxDurationS)
            .arg(spec.preRollS);
    if (spec.periods < 1 || spec.periods > StepTestSpec::kMaxPeriods)
        return QStringLiteral("the periods must be 1..%1, got %2")
            .arg(StepTestSpec::kMaxPeriods)
            .arg(spec.periods);
    if (spec.maxSpeedDps && spec.loop != StepLoop::Position)
        return QStringLiteral("a max speed goes with a position test only");
    return QString();
}

StepTestPlan StepTestPlan::make(const StepTestSpec &spec, std::optional<protocol::Series> series,
                                const safety::SoftLimits &limits,
                                const safety::DrivePosition &position)
{
    StepTestPlan plan;
    plan.m_spec = spec;
    plan.m_specError = checkSpec(spec);
    if (!plan.m_specError.isEmpty())
        return plan;
    double endS = 0;
    QVector<StepSetpoint> setpoints = timeline(spec, &endS);
    // Each target starts where the drive is: the read angle first, then the target before it.
    safety::DrivePosition at = position;
    for (int i = 0; i < setpoints.size(); ++i) {
        StepSetpoint &s = setpoints[i];
        const protocol::BuildResult built = build(spec, s.target);
        if (!built.ok()) {
            plan.m_specError = built.error.message();
            return plan;
        }
        const safety::MotionPlan motion =
            safety::MotionPlanner::plan(*built.request, series, limits, at);
        if (!motion.allowed()) {
            plan.m_refusal =
                StepRefusal{motion.verdict, i, int(setpoints.size()), s, spec.loop, series};
            return plan;
        }
        s.request = *motion.request;
        plan.m_bound = motion.bound;
        plan.m_boundDps = motion.boundDps;
        at.angleDeg = s.target;
    }
    plan.m_setpoints = setpoints;
    plan.m_endS = endS;
    return plan;
}

} // namespace lk::tuning
