#include "FreqCommand.h"

#include "Console.h"
#include "OrderedJson.h"
#include "TuningJson.h"

#include <text/VerdictText.h>
#include <tuning/FrequencyRunFile.h>

#include <cmath>

namespace lk::lkctl {

using tuning::FrequencySweepResult;
using tuning::StepTestFailure;

namespace {
void optionalReal(OrderedJson &o, const QString &key, std::optional<double> v, double unit)
{
    if (v)
        o.real(key, std::round(*v / unit) * unit);
    else
        o.null(key);
}

constexpr double kDefaultPositionAmplitudeDeg = 5;

QString figure(std::optional<double> v, const char *unit, int decimals)
{
    return v ? QStringLiteral("%1 %2").arg(*v, 0, 'f', decimals).arg(QLatin1String(unit))
             : QStringLiteral("none");
}
QString loopWord(tuning::SweepLoop loop)
{
    return loop == tuning::SweepLoop::Position ? QStringLiteral("position")
                                               : QStringLiteral("speed");
}
} // namespace

QString FreqCommand::summary() const
{
    return QStringLiteral(
        "measure the speed or position loop's frequency response (Bode) with a stepped sine");
}

QString FreqCommand::example() const
{
    return QStringLiteral(
        "lkctl freq 3 speed --from 1 --to 200 --amplitude 60 --port /dev/ttyUSB0");
}

QString FreqCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl freq ID speed|position [--from HZ] [--to HZ] [--points N]\n"
               "                  [--amplitude DPS|DEG] [--operating-point DPS] [--per-point S]\n"
               "                  [--save FILE] [LIMITS] (--port DEV [--baud N] | --sim SPEC)\n"
               "                  [--json]\n"
               "\n"
               "The speed loop's frequency response on drive ID. THE AXIS MUST BE FREE TO\n"
               "TURN: it runs at the operating point +- the amplitude for the whole sweep.\n"
               "\n"
               "position: the position loop's instead, around the angle the drive is at (read\n"
               "first, 0x92): a sine of the multi-turn target (0xA3, sent as 0xA4 at the speed\n"
               "limit) of --amplitude DEG (default 5, at most 180). It needs an angle window\n"
               "(min_angle_deg and max_angle_deg in --limits, exit 4 without one); the sine's\n"
               "extremes must lie inside it and its peak speed, 2 pi x --to x the amplitude,\n"
               "under the speed limit (else refused naming the limit, exit 4). The replies\n"
               "carry the speed: each point is the angle's response, the speed's over jw. The\n"
               "drive ends holding the angle it started at.\n"
               "Reads the drive's gains and acceleration limit (nothing runs without them)\n"
               "and its speed, checks the sine's extremes against the series and your limits\n"
               "(a refusal names the limit and sends NOTHING, exit 4), lifts the acceleration\n"
               "limit in RAM, then sends a stepped sine of the speed setpoint (speed, 0xA2) as\n"
               "fast as the bus answers: each frequency a whole number of cycles, the first one\n"
               "left to settle. Each reply is a sample; each frequency is fitted on the\n"
               "samples' real times. Frequencies above a quarter of the sample rate reached\n"
               "(a sixteenth for the position loop, measured through the replies' speed)\n"
               "are dropped (reason above_resolution). At the end the gains and acceleration\n"
               "read go back to RAM and the drive returns to the speed it had. Ctrl-C stops at\n"
               "once: motor off, the settings read back in RAM (exit 1). Nothing is written\n"
               "to ROM.\n"
               "\n"
               "Sweep options:\n"
               "  --from HZ              the lowest frequency, 0.1..500, default 1\n"
               "  --to HZ                the highest, --from..500, default 100\n"
               "  --points N             log-spaced frequencies, 1..60, default 12\n"
               "  --amplitude DPS|DEG    the sine's peak, default 50 dps (position: 5 deg)\n"
               "  --operating-point DPS  the speed the sine is centred on, default twice the\n"
               "                         amplitude (the rotor never stops: friction would bend\n"
               "                         the response); speed only\n"
               "  --per-point S          each frequency lasts at least this long, default 0.3\n"
               "  --save FILE            also save the run (FILE.lkfreq.json, lkstudio's\n"
               "                         Frequency response view opens it to overlay)\n"
               "%1"
               "  --json                 one line: command, id, loop, from_hz, to_hz, amplitude,\n"
               "                         operating_point, sample_rate_hz, resolved_hz, points\n"
               "                         (each hz, magnitude_db, phase_deg, quality 0..1,\n"
               "                         samples), dropped (each hz, reason), bandwidth_hz,\n"
               "                         phase_at_bandwidth_deg, peak_db, peak_hz (null when\n"
               "                         none), gains, sent, after\n"
               "\n"
               "%2"
               "\n"
               "Examples:\n"
               "  lkctl freq 3 speed --port /dev/ttyUSB0 --baud 1000000\n"
               "  lkctl freq 3 speed --from 2 --to 150 --amplitude 60 --sim 3:MF --json\n"
               "  lkctl freq 3 position --to 30 --amplitude 4 --limits window.json --sim 3:MF\n"
               "\n"
               "%3")
        .arg(MotionLimitOptions::helpText(), BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  4  refused for safety: the sine's centre, an extreme or (position) its\n"
                 "     peak speed breaks the series or one of your limits, or a position\n"
                 "     sweep has no angle window; nothing was sent\n")));
}

std::optional<FreqCommand::Plan> FreqCommand::parse(const ArgParser &parser, Console &console,
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
    tuning::FrequencySweepSpec &s = plan.spec;
    if (pos.at(1) == QLatin1String("position")) {
        s.loop = tuning::SweepLoop::Position;
        s.amplitude = kDefaultPositionAmplitudeDeg;
    } else if (pos.at(1) != QLatin1String("speed")) {
        return fail(QStringLiteral("unknown loop '%1': speed or position").arg(pos.at(1)));
    }
    const std::pair<const char *, double *> numbers[] = {{"from", &s.fromHz},
                                                         {"to", &s.toHz},
                                                         {"amplitude", &s.amplitude},
                                                         {"per-point", &s.minPointS}};
    for (const auto &[option, into] : numbers) {
        if (!parser.isSet(QLatin1String(option)))
            continue;
        const std::optional<double> v = parser.numberValue(QLatin1String(option), 0, &error);
        if (!v)
            return fail(error);
        *into = *v;
    }
    if (parser.isSet(QStringLiteral("operating-point"))) {
        if (s.loop == tuning::SweepLoop::Position)
            return fail(QStringLiteral("--operating-point is the speed loop's: a position sweep "
                                       "is centred on the angle the drive is at"));
        s.operatingPoint = parser.numberValue(QStringLiteral("operating-point"), -1e9, &error);
        if (!s.operatingPoint)
            return fail(error);
    }
    if (parser.isSet(QStringLiteral("points"))) {
        const auto n = parser.intValue(QStringLiteral("points"), 1,
                                       tuning::FrequencySweepSpec::kMaxPoints, &error);
        if (!n)
            return fail(error);
        s.points = int(*n);
    }
    const QString bad = tuning::FrequencySweepPlan::checkSpec(s);
    if (!bad.isEmpty())
        return fail(bad);
    const std::optional<MotionLimitOptions> limits = MotionLimitOptions::read(parser, &error);
    if (!limits)
        return fail(error);
    plan.limits = *limits;
    plan.json = parser.isSet(QStringLiteral("json"));
    return plan;
}

FrequencySweepResult FreqCommand::runSweep(LiveBus &bus, const Plan &plan,
                                           const safety::SoftLimits &limits) const
{
    tuning::FrequencySweepRunner runner(bus.session());
    // Ctrl-C: the stream halts, the motor goes off, the settings read go back to RAM.
    const tuning::FrequencySweepPlan expected =
        tuning::FrequencySweepPlan::make(plan.spec, std::nullopt, safety::SoftLimits{});
    return runToEnd<tuning::FrequencySweepRunner, FrequencySweepResult>(
        bus, runner, [&] { runner.start(plan.spec, limits); },
        int(expected.endS() * 1000) + LiveBus::kMaxWaitMs);
}

int FreqCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *o :
         {"from", "to", "points", "amplitude", "operating-point", "per-point", "save"})
        parser.addOption(QLatin1String(o), true);
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
    const bool position = plan->spec.loop == tuning::SweepLoop::Position;
    if (position && (!limits->minAngleDeg || !limits->maxAngleDeg)) {
        bus.refused(QStringLiteral("the position loop's sweep needs an angle window "
                                   "(min_angle_deg and max_angle_deg in --limits)"),
                    id);
        return kExitRefused;
    }
    const FrequencySweepResult result = runSweep(bus, *plan, *limits);
    const auto refusal = [&] {
        const bool angle = position && result.refusal.kind != safety::LimitKind::SoftSpeed &&
                           result.refusal.kind != safety::LimitKind::SeriesSpeed;
        bus.refused(QStringLiteral("the sweep's %1 %2: %3")
                        .arg(result.refusedDps)
                        .arg(angle ? QStringLiteral("deg") : QStringLiteral("dps"))
                        .arg(text::VerdictText::verdict(result.refusal, bus.session().series(id))),
                    id);
    };
    if (const auto failed = failureStatus(bus, console, result.failure, result.message, refusal))
        return *failed;
    if (parser.isSet(QStringLiteral("save")) &&
        !saveRun(parser.value(QStringLiteral("save")), bus.session().series(id), result, console))
        return kExitFailure;
    if (plan->json)
        printJson(console, *plan, result);
    else
        printText(console, *plan, result);
    return kExitOk;
}

bool FreqCommand::saveRun(const QString &path, std::optional<protocol::Series> series,
                          const FrequencySweepResult &result, Console &console) const
{
    tuning::FrequencyRun run;
    run.number = 1;
    run.ranAt = QDateTime::currentDateTimeUtc();
    run.driveId = result.spec.id;
    if (series)
        run.series = protocol::seriesName(*series);
    run.spec = result.spec;
    run.gains = result.gains;
    run.response = result.response;
    const QString failed = tuning::FrequencyRunFile::save(path, run);
    if (failed.isEmpty())
        return true;
    console.errLine(
        QStringLiteral("lkctl freq: the run was measured but not saved: %1").arg(failed));
    return false;
}

void FreqCommand::printJson(Console &console, const Plan &plan, const FrequencySweepResult &r) const
{
    const tuning::BodeFigures f = r.response.figures();
    OrderedJson o;
    o.text(QStringLiteral("command"), QStringLiteral("freq"))
        .integer(QStringLiteral("id"), plan.spec.id)
        .text(QStringLiteral("loop"), loopWord(r.spec.loop))
        .real(QStringLiteral("from_hz"), plan.spec.fromHz)
        .real(QStringLiteral("to_hz"), plan.spec.toHz)
        .real(QStringLiteral("amplitude"), plan.spec.amplitude)
        .real(QStringLiteral("operating_point"), r.spec.centre())
        .real(QStringLiteral("sample_rate_hz"), std::round(r.response.sampleRateHz * 10) / 10)
        .real(QStringLiteral("resolved_hz"), std::round(r.response.resolvedHz() * 10) / 10)
        .raw(QStringLiteral("points"), TuningJson::points(r.response))
        .raw(QStringLiteral("dropped"), TuningJson::dropped(r.response));
    optionalReal(o, QStringLiteral("bandwidth_hz"), f.bandwidthHz, 0.01);
    optionalReal(o, QStringLiteral("phase_at_bandwidth_deg"), f.phaseAtBandwidth, 0.1);
    optionalReal(o, QStringLiteral("peak_db"), f.peakDb, 0.01);
    optionalReal(o, QStringLiteral("peak_hz"), f.peakHz, 0.001);
    if (r.gains)
        o.raw(QStringLiteral("gains"), TuningJson::gains(*r.gains));
    o.integer(QStringLiteral("sent"), r.sent).text(QStringLiteral("after"), r.message);
    console.out(o.toJson() + '\n');
}

void FreqCommand::printText(Console &console, const Plan &plan, const FrequencySweepResult &r) const
{
    const bool position = r.spec.loop == tuning::SweepLoop::Position;
    console.outLine(QStringLiteral("Frequency response of drive %1's %2 loop: %3 +- %4 %5, "
                                   "%6..%7 Hz.")
                        .arg(plan.spec.id)
                        .arg(loopWord(r.spec.loop))
                        .arg(r.spec.centre())
                        .arg(plan.spec.amplitude)
                        .arg(position ? QStringLiteral("deg") : QStringLiteral("dps"))
                        .arg(plan.spec.fromHz)
                        .arg(plan.spec.toHz));
    if (r.gains && position)
        console.outLine(QStringLiteral("Gains: angle Kp %1 Ki %2 Kd %3; %4.")
                            .arg(r.gains->angle.kp)
                            .arg(r.gains->angle.ki)
                            .arg(r.gains->angle.kd)
                            .arg(TuningJson::speedGainsText(*r.gains)));
    else if (r.gains)
        console.outLine(QStringLiteral("Gains: %1.").arg(TuningJson::speedGainsText(*r.gains)));
    console.outLine(QStringLiteral("Sent %1 setpoints; %2 samples/s, so up to %3 Hz is resolved.")
                        .arg(r.sent)
                        .arg(r.response.sampleRateHz, 0, 'f', 1)
                        .arg(r.response.resolvedHz(), 0, 'f', 1));
    console.outLine(QStringLiteral("      Hz       dB      deg  quality"));
    for (const tuning::FrequencyPoint &p : r.response.points)
        console.outLine(QStringLiteral("%1 %2 %3 %4")
                            .arg(p.hz, 8, 'f', 2)
                            .arg(p.magnitudeDb, 8, 'f', 2)
                            .arg(p.phaseDeg, 8, 'f', 1)
                            .arg(p.quality, 8, 'f', 3));
    for (const tuning::DroppedFrequency &d : r.response.dropped)
        console.outLine(QStringLiteral("%1  not shown: %2")
                            .arg(d.hz, 8, 'f', 2)
                            .arg(QString::fromLatin1(TuningJson::droppedWord(d.reason))
                                     .replace(QLatin1Char('_'), QLatin1Char(' '))));
    const tuning::BodeFigures f = r.response.figures();
    console.outLine(QStringLiteral("Bandwidth (-3 dB): %1; phase there: %2; peak: %3 at %4.")
                        .arg(figure(f.bandwidthHz, "Hz", 2), figure(f.phaseAtBandwidth, "deg", 1),
                             figure(f.peakDb, "dB", 2), figure(f.peakHz, "Hz", 2)));
    console.outLine(QStringLiteral("After the sweep: %1.").arg(r.message));
}

} // namespace lk::lkctl
