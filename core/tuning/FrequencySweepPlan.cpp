#include "FrequencySweepPlan.h"

#include <protocol/RequestBuilder.h>
#include <safety/MotionPlanner.h>

#include <cmath>

namespace lk::tuning {

namespace {
using Spec = FrequencySweepSpec;
// The stream starts on the bus thread; the fit windows are placed on the samples' clock from
// the first setpoint's reply, a transaction later: the windows end this much early so that no
// sample of the next frequency falls into them.
constexpr double kWindowGuardS = 0.002;
constexpr double kPi = 3.14159265358979323846;
// Half an output turn of a direct drive: a sine around an angle, not a move.
constexpr double kMaxPositionAmplitudeDeg = 180;
} // namespace

double FrequencySweepSpec::peakSpeedDps() const
{
    return loop == SweepLoop::Position ? 2 * kPi * toHz * amplitude : std::abs(amplitude);
}

bool FrequencySweepPlan::checkExtremes(std::optional<protocol::Series> series,
                                       const safety::SoftLimits &limits)
{
    const FrequencySweepSpec &spec = m_spec;
    const bool position = spec.loop == SweepLoop::Position;
    safety::DrivePosition from;
    from.angleDeg = spec.operatingPoint;
    const double centre = spec.centre();
    QVector<std::pair<protocol::BuildResult, double>> checks;
    for (double v : {centre, centre + spec.amplitude, centre - spec.amplitude})
        checks.append({position ? protocol::build::multiPosition(spec.id, v)
                                : protocol::build::speed(spec.id, v),
                       v});
    if (position) // the setpoint's fastest: a speed command of that speed meets the same limits
        checks.append({protocol::build::speed(spec.id, spec.peakSpeedDps()), spec.peakSpeedDps()});
    for (const auto &[built, value] : checks) {
        if (!built.ok()) {
            m_specError = built.error.message();
            return false;
        }
        const safety::MotionPlan motion =
            safety::MotionPlanner::plan(*built.request, series, limits, from);
        if (!motion.allowed()) {
            m_verdict = motion.verdict;
            m_refusedDps = value;
            return false;
        }
    }
    return true;
}

QVector<double> FrequencySweepPlan::frequencies(double from, double to, int points)
{
    QVector<double> out;
    if (points <= 1) {
        out.append(from);
        return out;
    }
    const double ratio = std::log(to / from) / (points - 1);
    for (int i = 0; i < points; ++i)
        out.append(from * std::exp(ratio * i));
    return out;
}

QString FrequencySweepPlan::checkSpec(const FrequencySweepSpec &s)
{
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(s.fromHz) || !finite(s.toHz) || s.fromHz < Spec::kMinHz || s.toHz > Spec::kMaxHz ||
        s.fromHz > s.toHz)
        return QStringLiteral("the frequencies must run from %1 up to %2 Hz, got %3..%4")
            .arg(Spec::kMinHz)
            .arg(Spec::kMaxHz)
            .arg(s.fromHz)
            .arg(s.toHz);
    if (s.points < 1 || s.points > Spec::kMaxPoints)
        return QStringLiteral("the points must be 1..%1, got %2")
            .arg(Spec::kMaxPoints)
            .arg(s.points);
    const bool position = s.loop == SweepLoop::Position;
    if (!finite(s.amplitude) || s.amplitude <= 0)
        return QStringLiteral("the amplitude must be above 0 %1, got %2")
            .arg(position ? QStringLiteral("deg") : QStringLiteral("dps"))
            .arg(s.amplitude);
    if (position && s.amplitude > kMaxPositionAmplitudeDeg)
        return QStringLiteral("the amplitude of a position sweep must be at most %1 deg, got %2")
            .arg(kMaxPositionAmplitudeDeg)
            .arg(s.amplitude);
    if (s.operatingPoint && !finite(*s.operatingPoint))
        return QStringLiteral("the operating point must be a number");
    if (!finite(s.leadInS) || s.leadInS < bus::SetpointWaveform::kMinPeriodS || s.leadInS > 60)
        return QStringLiteral("the lead-in must be %1..60 s, got %2")
            .arg(bus::SetpointWaveform::kMinPeriodS)
            .arg(s.leadInS);
    if (!finite(s.minPointS) || s.minPointS <= 0 || s.minPointS > 60)
        return QStringLiteral("the time per frequency must be 0..60 s, got %1").arg(s.minPointS);
    return QString();
}

FrequencySweepPlan FrequencySweepPlan::make(const FrequencySweepSpec &spec,
                                            std::optional<protocol::Series> series,
                                            const safety::SoftLimits &limits)
{
    FrequencySweepPlan plan;
    plan.m_spec = spec;
    plan.m_specError = checkSpec(spec);
    if (!plan.m_specError.isEmpty())
        return plan;
    // The extremes and the centre, as every setpoint will be checked on the bus thread: a
    // refusal here names the limit before anything moves.
    if (!plan.checkExtremes(series, limits))
        return plan;
    bus::SetpointWaveform::Settings &w = plan.m_settings;
    w.waveform = bus::SetpointWaveform::Waveform::SteppedSine;
    w.target = spec.loop == SweepLoop::Position ? bus::SetpointWaveform::Target::Position
                                                : bus::SetpointWaveform::Target::Speed;
    w.amplitude = spec.amplitude;
    w.offset = spec.centre();
    w.periodS = spec.leadInS;
    w.rateHz = spec.rateHz;
    double start = spec.leadInS;
    for (double hz : frequencies(spec.fromHz, spec.toHz, spec.points)) {
        const int cycles = std::max(Spec::kSettleCycles + Spec::kMinFitCycles + 1,
                                    int(std::ceil(spec.minPointS * hz)));
        bus::SetpointWaveform::SineStep step{hz, cycles};
        w.steps.append(step);
        SweepSegment s;
        s.hz = hz;
        s.startS = start;
        s.endS = start + step.durationS();
        s.fitFromS = start + Spec::kSettleCycles / hz;
        const int fitCycles = int(std::floor((s.endS - kWindowGuardS - s.fitFromS) * hz));
        s.fitToS = s.fitFromS + fitCycles / hz;
        plan.m_segments.append(s);
        start = s.endS;
    }
    plan.m_endS = start;
    return plan;
}

} // namespace lk::tuning
