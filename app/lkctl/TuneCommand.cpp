#include "TuneCommand.h"

#include "Console.h"
#include "OrderedJson.h"
#include "TuningJson.h"

#include <text/VerdictText.h>

#include <cmath>

namespace lk::lkctl {

using tuning::CandidateScore;
using tuning::CandidateVerdict;
using tuning::GainSearchResult;
using tuning::StepTestFailure;

namespace {
/// The largest position step: within one output turn of the start, as StepTestPlan checks.
constexpr double kMaxPositionStepDeg = 180;

const char *verdictWord(CandidateVerdict v)
{
    switch (v) {
    case CandidateVerdict::Accepted:
        return "accepted";
    case CandidateVerdict::Overshoot:
        return "overshoot";
    case CandidateVerdict::Oscillates:
        return "oscillates";
    case CandidateVerdict::NotSettled:
        return "not_settled";
    case CandidateVerdict::Saturated:
        return "saturated";
    case CandidateVerdict::Growing:
        return "growing";
    }
    return "";
}

void metric(OrderedJson &o, const QString &key, const tuning::Metric &m, double unit)
{
    if (m.known())
        o.real(key, std::round(*m.value / unit) * unit);
    else
        o.null(key);
}

bool isPosition(const GainSearchResult &r)
{
    return r.spec.loop == tuning::StepLoop::Position;
}

/// "speed" or "angle": the prefix of the searched loop's gains (read_pid's names).
QString gainPrefix(tuning::StepLoop loop)
{
    return loop == tuning::StepLoop::Position ? QStringLiteral("angle") : QStringLiteral("speed");
}

/// "speed Kp 50 Ki 40" / "angle Kp 100 Ki 100" (and "Kd 0" on V2.35).
QString loopGainsText(const tuning::LoopGains &g, tuning::StepLoop loop)
{
    const tuning::PidTriple &t = tuning::GainSearchStrategy::tuned(g, loop);
    QString text = QStringLiteral("%1 Kp %2 Ki %3").arg(gainPrefix(loop)).arg(t.kp).arg(t.ki);
    if (g.generation == protocol::Generation::V2_35)
        text += QStringLiteral(" Kd %1").arg(t.kd);
    return text;
}

QByteArray candidateJson(const CandidateScore &c, tuning::StepLoop loop)
{
    OrderedJson o;
    const tuning::PidTriple &t = tuning::GainSearchStrategy::tuned(c.gains, loop);
    const QString prefix = gainPrefix(loop);
    o.integer(prefix + QStringLiteral("_kp"), t.kp).integer(prefix + QStringLiteral("_ki"), t.ki);
    if (c.gains.generation == protocol::Generation::V2_35)
        o.integer(prefix + QStringLiteral("_kd"), t.kd);
    metric(o, QStringLiteral("rise_time_s"), c.metrics.riseTimeS, 0.0001);
    metric(o, QStringLiteral("overshoot_pct"), c.metrics.overshootPct, 0.01);
    metric(o, QStringLiteral("settling_time_s"), c.metrics.settling2S, 0.0001);
    metric(o, QStringLiteral("oscillations"), c.metrics.oscillations, 1);
    metric(o, QStringLiteral("saturated_s"), c.metrics.saturatedS, 0.0001);
    o.real(QStringLiteral("error_area_s"), std::round(c.errorAreaS * 1e5) / 1e5)
        .text(QStringLiteral("verdict"), QLatin1String(verdictWord(c.verdict)));
    return o.toJson();
}

/// The Bode figures of one response: {"bandwidth_hz":..,"phase_at_bandwidth_deg":..,
/// "peak_db":..,"peak_hz":..,"points":N} (null figures: not measured or never 3 dB down).
QByteArray bodeJson(const tuning::FrequencyResponse &r)
{
    const tuning::BodeFigures f = r.figures();
    OrderedJson o;
    const std::pair<const char *, std::optional<double>> figures[] = {
        {"bandwidth_hz", f.bandwidthHz},
        {"phase_at_bandwidth_deg", f.phaseAtBandwidth},
        {"peak_db", f.peakDb},
        {"peak_hz", f.peakHz}};
    for (const auto &[key, value] : figures) {
        if (value)
            o.real(QLatin1String(key), std::round(*value * 100) / 100);
        else
            o.null(QLatin1String(key));
    }
    o.integer(QStringLiteral("points"), r.points.size());
    return o.toJson();
}

QString bodeText(const tuning::FrequencyResponse &r)
{
    const tuning::BodeFigures f = r.figures();
    const auto v = [](std::optional<double> x, int decimals) {
        return x ? QString::number(*x, 'f', decimals) : QStringLiteral("?");
    };
    return QStringLiteral("bandwidth %1 Hz (phase %2 deg), peak %3 dB at %4 Hz")
        .arg(v(f.bandwidthHz, 1), v(f.phaseAtBandwidth, 0), v(f.peakDb, 2), v(f.peakHz, 1));
}

QString candidateText(const CandidateScore &c, tuning::StepLoop loop)
{
    const tuning::PidTriple &t = tuning::GainSearchStrategy::tuned(c.gains, loop);
    const auto v = [](const tuning::Metric &m, double scale, int decimals) {
        return m.known() ? QString::number(*m.value * scale, 'f', decimals) : QStringLiteral("?");
    };
    return QStringLiteral("%1 %2 %3 %4 %5  %6")
        .arg(t.kp, 5)
        .arg(t.ki, 5)
        .arg(v(c.metrics.riseTimeS, 1e3, 1), 9)
        .arg(v(c.metrics.overshootPct, 1, 1), 9)
        .arg(c.errorAreaS * 1e3, 9, 'f', 2)
        .arg(QString::fromLatin1(verdictWord(c.verdict)).replace(QLatin1Char('_'), ' '));
}
} // namespace

QString TuneCommand::summary() const
{
    return QStringLiteral("suggest speed- or position-loop gains from short step tests (writes "
                          "only with --write ram)");
}

QString TuneCommand::example() const
{
    return QStringLiteral("lkctl tune 3 speed --max-overshoot 5 --port /dev/ttyUSB0");
}

QString TuneCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl tune ID speed [--max-overshoot PCT] [--from DPS] [--to DPS]\n"
               "                  [--bode] [--write ram] [LIMITS]\n"
               "       lkctl tune ID position [--max-overshoot PCT] [--step DEG]\n"
               "                  [--write ram] --limits FILE (with an angle window)\n"
               "                  (--port DEV [--baud N] | --sim SPEC)\n"
               "                  [--json]\n"
               "\n"
               "Suggested speed-loop gains for drive ID. THE AXIS MUST BE FREE TO TURN: it\n"
               "steps between FROM and TO (and may overshoot them) for up to a minute. Reads\n"
               "the gains and acceleration limit (nothing runs without them), lifts the limit\n"
               "in RAM, then for each candidate writes its speed Kp and Ki to RAM and runs a\n"
               "square of short speed steps FROM -> TO -> FROM (every setpoint checked against\n"
               "the series and your limits: a refusal sends nothing, exit 4). Candidates: the\n"
               "gains read first, then rows of Kp (x1.3 per row), Ki lowered by 1.5 within a\n"
               "row (while that lowers the overshoot) until one is accepted: overshoot at most\n"
               "PCT, at most two swings, settled within 2 %, the current never at its limit.\n"
               "Once a row finds none, three candidates narrow Kp down between it and the last\n"
               "accepted row. The best is the fastest rise time (10-90 %) accepted. The current\n"
               "at its limit or swings that grow end the search at once. At the end the gains\n"
               "read go back to RAM and the drive returns to the speed it had; the best is\n"
               "suggested beside them. Ctrl-C stops at once: motor off, the gains read back\n"
               "in RAM (exit 1).\n"
               "\n"
               "position: the position loop's Kp and Ki instead (the angle gains; V2.3's are\n"
               "uint8, V2.35's and CAN V2.36's their own parameters), scored the same way by a\n"
               "square of position steps of DEG from the angle the drive is at (read first)\n"
               "and back, at most the speed limit fast. It needs an angle window\n"
               "(min_angle_deg and max_angle_deg in --limits; exit 4 without one); the steps\n"
               "go down from the angle when the window has no room above it, and every target\n"
               "is checked against it. The drive ends holding the angle it started at.\n"
               "\n"
               "Tune options:\n"
               "  --max-overshoot PCT    the overshoot bound, 0..100 %, default 5\n"
               "  --from DPS, --to DPS   the steps' speeds, default 100 and 300 (away from 0,\n"
               "                         where friction would bend them)\n"
               "  --step DEG             position: the steps' size in rotor degrees, more\n"
               "                         than 0 and at most 180, default 10\n"
               "  --bode                 then measure the speed loop's frequency response with\n"
               "                         the gains read and with the best's (two short sweeps,\n"
               "                         5-100 Hz around the steps' middle, about 10 s more;\n"
               "                         the best's gains are in RAM only for their sweep)\n"
               "  --write ram            write the best candidate's gains to RAM at the end\n"
               "                         (never ROM: that is lkctl write pid, after checking)\n"
               "%1"
               "  --json                 one line: command, id, loop, max_overshoot_pct,\n"
               "                         from, to (position: step_deg, negative when the\n"
               "                         steps went down, and start_angle_deg), gains_read,\n"
               "                         candidates (each speed_kp, speed_ki, speed_kd on\n"
               "                         V2.35 (position: angle_kp, ...), rise_time_s,\n"
               "                         overshoot_pct, settling_time_s, oscillations,\n"
               "                         saturated_s, error_area_s, verdict), best (index or\n"
               "                         null), before, after (the read gains' and the best's\n"
               "                         candidate), suggested (gains or null), written (\"ram\"\n"
               "                         or null), stopped_by_instability, seconds, after_text;\n"
               "                         with --bode also bode: before and after (each\n"
               "                         bandwidth_hz, phase_at_bandwidth_deg, peak_db,\n"
               "                         peak_hz, points), or null without a best\n"
               "\n"
               "%2"
               "\n"
               "Examples:\n"
               "  lkctl tune 3 speed --port /dev/ttyUSB0 --baud 1000000\n"
               "  lkctl tune 3 speed --max-overshoot 2 --write ram --sim 3:MF --json\n"
               "  lkctl tune 3 speed --bode --sim 3:MF --json\n"
               "  lkctl tune 3 position --step 5 --limits window.json --sim 3:MF\n"
               "\n"
               "%3")
        .arg(MotionLimitOptions::helpText(), BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  4  refused for safety: a step breaks the series or one of your limits,\n"
                 "     or a position search has no angle window; no step was sent and the\n"
                 "     gains read are back in RAM\n")));
}

std::optional<TuneCommand::Plan> TuneCommand::parse(const ArgParser &parser, Console &console,
                                                    int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return std::nullopt;
    };
    const QStringList &pos = parser.positionals();
    if (pos.size() != 2)
        return fail(QStringLiteral("expected ID speed|position"));
    Plan plan;
    QString error;
    const std::optional<int> id = parseId(pos.at(0), &error);
    if (!id)
        return fail(error);
    plan.spec.id = *id;
    const bool position = pos.at(1) == QLatin1String("position");
    if (!position && pos.at(1) != QLatin1String("speed"))
        return fail(QStringLiteral("unknown loop '%1': speed or position").arg(pos.at(1)));
    if (position) {
        plan.spec = tuning::GainSearchSpec::forPosition(*id);
        for (const char *speedOnly : {"from", "to", "bode"})
            if (parser.isSet(QLatin1String(speedOnly)))
                return fail(QStringLiteral("--%1 is the speed loop's: a position search steps "
                                           "--step DEG from the angle the drive is at")
                                .arg(QLatin1String(speedOnly)));
    } else if (parser.isSet(QStringLiteral("step"))) {
        return fail(QStringLiteral("--step is the position loop's: a speed search steps "
                                   "--from DPS --to DPS"));
    }
    const std::pair<const char *, double *> numbers[] = {
        {"max-overshoot", &plan.spec.maxOvershootPct},
        {"from", &plan.spec.from},
        {"to", &plan.spec.to},
        {"step", &plan.spec.to}};
    for (const auto &[option, into] : numbers) {
        if (!parser.isSet(QLatin1String(option)))
            continue;
        const std::optional<double> v = parser.numberValue(QLatin1String(option), -1e9, &error);
        if (!v)
            return fail(error);
        *into = *v;
    }
    if (position && !(plan.spec.to > 0 && plan.spec.to <= kMaxPositionStepDeg))
        return fail(QStringLiteral("--step must be more than 0 and at most %1 deg, got %2")
                        .arg(kMaxPositionStepDeg)
                        .arg(plan.spec.to));
    if (!(plan.spec.maxOvershootPct >= 0 && plan.spec.maxOvershootPct <= 100))
        return fail(QStringLiteral("--max-overshoot must be 0..100, got %1")
                        .arg(plan.spec.maxOvershootPct));
    if (parser.isSet(QStringLiteral("write"))) {
        if (parser.value(QStringLiteral("write")) != QLatin1String("ram"))
            return fail(QStringLiteral("--write takes ram (ROM is a separate, confirmed step: "
                                       "lkctl write pid ... --rom)"));
        plan.writeRam = true;
    }
    const std::optional<MotionLimitOptions> limits = MotionLimitOptions::read(parser, &error);
    if (!limits)
        return fail(error);
    plan.limits = *limits;
    plan.json = parser.isSet(QStringLiteral("json"));
    plan.spec.measureBode = parser.isSet(QStringLiteral("bode"));
    return plan;
}

GainSearchResult TuneCommand::runSearch(LiveBus &bus, const Plan &plan,
                                        const safety::SoftLimits &limits) const
{
    tuning::GainSearchRunner runner(bus.session());
    // Ctrl-C: the step halts, the motor goes off, the gains read go back to RAM.
    return runToEnd<tuning::GainSearchRunner, GainSearchResult>(
        bus, runner, [&] { runner.start(plan.spec, limits); }, 2 * LiveBus::kMaxWaitMs);
}

bool TuneCommand::writeBest(LiveBus &bus, const GainSearchResult &r) const
{
    const tuning::LoopGains &best = r.candidates[*r.best].gains;
    // Absolute values: the session's retries are the only repeats.
    for (const protocol::Request &request : best.ramWrites(r.spec.id)) {
        const bus::RequestResult result = bus.request(request);
        if (!result.ok()) {
            bus.reportFailure(result);
            bus.error(QStringLiteral("the suggested gains were not all written: read them back "
                                     "with 'lkctl read %1 pid'")
                          .arg(r.spec.id));
            return false;
        }
    }
    return true;
}

int TuneCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *o : {"max-overshoot", "from", "to", "step", "write"})
        parser.addOption(QLatin1String(o), true);
    parser.addOption(QStringLiteral("bode"), false);
    MotionLimitOptions::declare(parser);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    LiveBus bus(console, name());
    const int id = plan->spec.id;
    const std::optional<safety::SoftLimits> limits =
        openDrive(bus, *busOptions, id, plan->limits, console, &status);
    if (!limits)
        return status;
    if (plan->spec.loop == tuning::StepLoop::Position &&
        (!limits->minAngleDeg || !limits->maxAngleDeg)) {
        bus.refused(QStringLiteral("the position loop's search needs an angle window "
                                   "(min_angle_deg and max_angle_deg in --limits)"),
                    id);
        return kExitRefused;
    }
    const GainSearchResult result = runSearch(bus, *plan, *limits);
    const auto refusal = [&] { bus.refused(text::VerdictText::stepRefusal(result.refusal), id); };
    if (const auto failed = failureStatus(bus, console, result.failure, result.message, refusal))
        return *failed;
    const bool write = plan->writeRam && result.best && result.read &&
                       result.candidates[*result.best].gains != *result.read;
    if (write && !writeBest(bus, result))
        return kExitFailure;
    if (plan->json)
        printJson(console, result, write);
    else
        printText(console, result, write);
    return kExitOk;
}

void TuneCommand::printJson(Console &console, const GainSearchResult &r, bool written) const
{
    OrderedJson o;
    o.text(QStringLiteral("command"), QStringLiteral("tune"))
        .integer(QStringLiteral("id"), r.spec.id)
        .text(QStringLiteral("loop"),
              isPosition(r) ? QStringLiteral("position") : QStringLiteral("speed"))
        .real(QStringLiteral("max_overshoot_pct"), r.spec.maxOvershootPct);
    if (isPosition(r)) {
        // The steps' size as asked and the way they went (-1: down, the window's room).
        o.real(QStringLiteral("step_deg"), r.spec.to * r.direction);
        if (r.startAngle)
            o.real(QStringLiteral("start_angle_deg"), std::round(*r.startAngle * 100) / 100);
        else
            o.null(QStringLiteral("start_angle_deg"));
    } else {
        o.real(QStringLiteral("from"), r.spec.from).real(QStringLiteral("to"), r.spec.to);
    }
    if (r.read)
        o.raw(QStringLiteral("gains_read"), TuningJson::gains(*r.read));
    QByteArray list = "[";
    for (const CandidateScore &c : r.candidates)
        list += (list.size() > 1 ? "," : "") + candidateJson(c, r.spec.loop);
    o.raw(QStringLiteral("candidates"), list + ']');
    if (r.best)
        o.integer(QStringLiteral("best"), *r.best);
    else
        o.null(QStringLiteral("best"));
    if (r.baseline)
        o.raw(QStringLiteral("before"), candidateJson(r.candidates[*r.baseline], r.spec.loop));
    else
        o.null(QStringLiteral("before"));
    if (r.best) {
        o.raw(QStringLiteral("after"), candidateJson(r.candidates[*r.best], r.spec.loop));
        o.raw(QStringLiteral("suggested"), TuningJson::gains(r.candidates[*r.best].gains));
    } else {
        o.null(QStringLiteral("after")).null(QStringLiteral("suggested"));
    }
    if (written)
        o.text(QStringLiteral("written"), QStringLiteral("ram"));
    else
        o.null(QStringLiteral("written"));
    o.boolean(QStringLiteral("stopped_by_instability"), r.stoppedByInstability)
        .real(QStringLiteral("seconds"), std::round(r.seconds * 10) / 10)
        .text(QStringLiteral("after_text"), r.message);
    if (r.spec.measureBode) {
        if (r.bodeRead && r.bodeBest)
            o.raw(QStringLiteral("bode"), OrderedJson()
                                              .raw(QStringLiteral("before"), bodeJson(*r.bodeRead))
                                              .raw(QStringLiteral("after"), bodeJson(*r.bodeBest))
                                              .toJson());
        else
            o.null(QStringLiteral("bode"));
    }
    console.out(o.toJson() + '\n');
}

void TuneCommand::printText(Console &console, const GainSearchResult &r, bool written) const
{
    const QString steps =
        isPosition(r)
            ? QStringLiteral("position loop: steps of %1 deg from %2 deg")
                  .arg(r.spec.to * r.direction)
                  .arg(r.startAngle ? QString::number(*r.startAngle, 'f', 2) : QStringLiteral("?"))
            : QStringLiteral("speed loop: steps %1 <-> %2 dps").arg(r.spec.from).arg(r.spec.to);
    console.outLine(QStringLiteral("Gain search on drive %1's %2, overshoot at most %3 %, %4 "
                                   "candidates in %5 s.")
                        .arg(r.spec.id)
                        .arg(steps)
                        .arg(r.spec.maxOvershootPct)
                        .arg(r.candidates.size())
                        .arg(r.seconds, 0, 'f', 1));
    console.outLine(QStringLiteral("   Kp    Ki   rise ms  overshoot  area ms  verdict"));
    for (const CandidateScore &c : r.candidates)
        console.outLine(candidateText(c, r.spec.loop));
    if (r.stoppedByInstability)
        console.outLine(QStringLiteral("The last candidate showed instability: the search "
                                       "stopped there."));
    if (!r.best) {
        console.outLine(QStringLiteral("No candidate met the bounds: nothing is suggested."));
    } else {
        console.outLine(
            QStringLiteral("Before: %1").arg(candidateText(r.candidates[0], r.spec.loop)));
        console.outLine(
            QStringLiteral("Best:   %1").arg(candidateText(r.candidates[*r.best], r.spec.loop)));
        console.outLine(QStringLiteral("Suggested: %1 (the rest as read)%2.")
                            .arg(loopGainsText(r.candidates[*r.best].gains, r.spec.loop),
                                 written
                                     ? QStringLiteral(", written to RAM")
                                     : QStringLiteral("; not written (--write ram writes it)")));
    }
    if (r.bodeRead && r.bodeBest) {
        console.outLine(QStringLiteral("Bode before: %1.").arg(bodeText(*r.bodeRead)));
        console.outLine(QStringLiteral("Bode best:   %1.").arg(bodeText(*r.bodeBest)));
    }
    console.outLine(QStringLiteral("After the search: %1.").arg(r.message));
}

} // namespace lk::lkctl
