#include "StepCommand.h"

#include "Console.h"
#include "DriveParams.h"
#include "OrderedJson.h"
#include "ReadCommand.h"
#include "ReplyText.h"

#include <protocol/FieldJson.h>
#include <text/VerdictText.h>
#include <tuning/StepMetrics.h>
#include <tuning/StepRunJson.h>

#include <QtCore/QDateTime>

#include <QtCore/QJsonObject>

#include <cmath>

namespace lk::lkctl {

using tuning::EdgeMetrics;
using tuning::Metric;
using tuning::StepLoop;
using tuning::StepSetpoint;
using tuning::StepTestFailure;
using tuning::StepTestResult;

namespace {

/// One metric of an edge as lkctl prints it for people (the JSON is StepRunJson's).
struct MetricRow {
    const char *label; ///< text label
    Metric EdgeMetrics::*member;
    enum Unit { Seconds, Percent, Value, Effort } unit;
};

const MetricRow kRows[] = {
    {"rise time 10-90 %", &EdgeMetrics::riseTimeS, MetricRow::Seconds},
    {"overshoot", &EdgeMetrics::overshootPct, MetricRow::Percent},
    {"settling time 2 %", &EdgeMetrics::settling2S, MetricRow::Seconds},
    {"settling time 5 %", &EdgeMetrics::settling5S, MetricRow::Seconds},
    {"steady-state error", &EdgeMetrics::steadyStateError, MetricRow::Value},
    {"peak iq", &EdgeMetrics::peakEffort, MetricRow::Effort},
    {"saturated", &EdgeMetrics::saturatedS, MetricRow::Seconds},
    {"oscillations", &EdgeMetrics::oscillations, MetricRow::Value},
};

const char *roleName(StepSetpoint::Role role)
{
    switch (role) {
    case StepSetpoint::Role::PreRoll:
        return "pre_roll";
    case StepSetpoint::Role::Edge:
        return "edge";
    case StepSetpoint::Role::Return:
        return "return";
    }
    return "";
}

QString unitOf(StepLoop loop)
{
    return loop == StepLoop::Speed ? QStringLiteral("dps") : QStringLiteral("deg");
}

/// The keys of StepRunJson::metricsObject() in the order lkctl prints them; each unknown
/// metric's "<key>_why" follows it.
const char *const kMetricKeys[] = {
    "rise_time_s",        "overshoot_pct", "settling_time_s", "settling_time_5pct_s",
    "steady_state_error", "peak_iq_a",     "peak_power",      "saturated_s",
    "oscillations",       "samples",       "sample_rate_hz"};

/// StepRunJson's metrics (the one mapping of metrics to JSON), in kMetricKeys order.
void addMetrics(OrderedJson &o, const QJsonObject &metrics)
{
    for (const char *k : kMetricKeys) {
        const QString key = QLatin1String(k);
        if (!metrics.contains(key))
            continue;
        const QJsonValue v = metrics.value(key);
        if (v.isNull())
            o.null(key);
        else if (key == QLatin1String("samples") || key == QLatin1String("oscillations"))
            o.integer(key, v.toInteger());
        else
            o.real(key, v.toDouble());
        const QString why = key + QLatin1String("_why");
        if (metrics.contains(why))
            o.text(why, metrics.value(why).toString());
    }
}

/// The trace's clock from its first sample (the pre-roll's reply).
double originOf(const StepTestResult &r)
{
    if (r.trace.size() > 0)
        return r.trace.time.first();
    return r.sent.isEmpty() ? 0 : r.sent.first().time;
}

/// A time on the trace's clock from its origin, to 0.1 ms (as StepRunJson rounds times).
double since(const StepTestResult &r, double t)
{
    return std::round((t - originOf(r)) * 1e4) / 1e4;
}

QByteArray sentJson(const StepTestResult &r)
{
    QByteArray out = "[";
    for (const tuning::StepSent &s : r.sent) {
        OrderedJson o;
        o.text(QStringLiteral("role"), QLatin1String(roleName(s.setpoint.role)))
            .real(QStringLiteral("at_s"), s.setpoint.atS)
            .real(QStringLiteral("target"), s.setpoint.target);
        if (std::isnan(s.time))
            o.null(QStringLiteral("time_s"));
        else
            o.real(QStringLiteral("time_s"), since(r, s.time));
        o.boolean(QStringLiteral("acknowledged"), s.acknowledged)
            .text(QStringLiteral("command"),
                  protocol::CommandTable::name(s.setpoint.request.command))
            .fields(QStringLiteral("fields"),
                    protocol::FieldJson::requestFields(s.setpoint.request));
        out += (out.size() > 1 ? "," : "") + o.toJson();
    }
    return out + ']';
}

QString metricText(const Metric &metric, MetricRow::Unit unit, const QString &valueUnit, bool power)
{
    if (!metric.known())
        return QStringLiteral("unknown (%1)")
            .arg(tuning::StepRunJson::gapWord(metric.gap).replace(QLatin1Char('_'), ' '));
    const double v = *metric.value;
    switch (unit) {
    case MetricRow::Seconds:
        return QStringLiteral("%1 s").arg(v, 0, 'f', 4);
    case MetricRow::Percent:
        return QStringLiteral("%1 %").arg(v, 0, 'f', 1);
    case MetricRow::Value:
        return QStringLiteral("%1 %2").arg(v, 0, 'g', 4).arg(valueUnit).trimmed();
    case MetricRow::Effort:
        return power ? QStringLiteral("%1 (power, of 1000)").arg(v, 0, 'g', 4)
                     : QStringLiteral("%1 A").arg(v, 0, 'f', 3);
    }
    return QString();
}

} // namespace

QString StepCommand::summary() const
{
    return QStringLiteral("run a step test on the speed or position loop and print its metrics");
}

QString StepCommand::example() const
{
    return QStringLiteral("lkctl step 3 speed 0 360 --port /dev/ttyUSB0");
}

QString StepCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl step ID speed|position FROM TO [--duration S] [--periods N]\n"
               "                  [--pre-roll S] [--max-speed DPS] [LIMITS]\n"
               "                  (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "A step test on drive ID: reads its gains (read_pid on V2.3; angle_pid,\n"
               "speed_pid and iq_pid on V2.35) and where it is (read_state2 for speed,\n"
               "read_multi_turn for position), checks EVERY setpoint against the series and\n"
               "your limits (a refusal names the limit and sends NOTHING, exit 4), then sends\n"
               "FROM, holds it for the pre-roll, steps to TO and records the drive's replies\n"
               "at the bus's full rate (the poll plan focuses on the drive). Prints the\n"
               "step-response metrics of the first edge and the sample rate reached.\n"
               "\n"
               "  speed FROM TO          speeds in dps (speed, 0xA2); a single step returns\n"
               "                         to FROM at its end; the drive is left turning at\n"
               "                         FROM (stop it with 'lkctl stop ID' or 'lkctl off')\n"
               "  position FROM TO       multi-turn angles in rotor deg (multi_position_limited,\n"
               "                         0xA4, at your speed limit or --max-speed); FROM may lie\n"
               "                         one output turn from the drive's angle, TO one output\n"
               "                         turn from FROM; the drive holds its last target\n"
               "Test options:\n"
               "  --duration S           how long each step (each half-period) is held, "
               "0.01..60,\n"
               "                         default 1\n"
               "  --periods N            1 (default): one step FROM -> TO; 2..100: a square of\n"
               "                         N periods (TO, FROM, ...), ending at FROM\n"
               "  --pre-roll S           how long FROM is held before the first edge, "
               "0.01..60,\n"
               "                         default 1\n"
               "  --max-speed DPS        position only: a lower max speed than your speed limit\n"
               "%1"
               "  --json                 one line: command, id, loop, from, to, duration_s,\n"
               "                         periods, pre_roll_s, the first edge's rise_time_s,\n"
               "                         overshoot_pct, settling_time_s, settling_time_5pct_s,\n"
               "                         steady_state_error, peak_iq_a (peak_power on MS),\n"
               "                         saturated_s, oscillations (null when unknown, the\n"
               "                         reason in <key>_why), samples, sample_rate_hz, gains,\n"
               "                         speed_bound, sent (each setpoint: role, at_s, target,\n"
               "                         time_s, acknowledged, command, fields), edges (each\n"
               "                         edge's time_s, from, to and metrics), still_moving\n"
               "\n"
               "%2"
               "\n"
               "Examples:\n"
               "  lkctl step 3 speed 0 360 --port /dev/ttyUSB0\n"
               "  lkctl step 3 position 0 90 --duration 0.5 --periods 3 --port ttyUSB0 --json\n"
               "  lkctl step 3 speed 0 720 --max-speed-dps 360 --sim 3:MF   (refused, exit 4)\n"
               "\n"
               "%3")
        .arg(MotionLimitOptions::helpText(), BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  4  refused for safety: a setpoint breaks the series or one of your limits\n"
                 "     (the message names the setpoint, the limit and both values); nothing\n"
                 "     was sent\n")));
}

bool StepCommand::readTiming(const ArgParser &parser, tuning::StepTestSpec &spec,
                             QString *error) const
{
    for (const auto &[option, into] :
         {std::pair{"duration", &spec.durationS}, std::pair{"pre-roll", &spec.preRollS}}) {
        if (!parser.isSet(QLatin1String(option)))
            continue;
        const std::optional<double> v = parser.numberValue(QLatin1String(option), 0, error);
        if (!v)
            return false;
        *into = *v;
    }
    if (parser.isSet(QStringLiteral("periods"))) {
        const auto n =
            parser.intValue(QStringLiteral("periods"), 1, tuning::StepTestSpec::kMaxPeriods, error);
        if (!n)
            return false;
        spec.periods = int(*n);
    }
    if (parser.isSet(QStringLiteral("max-speed"))) {
        spec.maxSpeedDps = parser.numberValue(QStringLiteral("max-speed"), 0, error);
        if (!spec.maxSpeedDps)
            return false;
    }
    return true;
}

std::optional<StepCommand::Plan> StepCommand::parse(const ArgParser &parser, Console &console,
                                                    int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return std::nullopt;
    };
    const QStringList &pos = parser.positionals();
    if (pos.size() != 4)
        return fail(QStringLiteral("expected ID speed|position FROM TO"));
    Plan plan;
    QString error;
    const std::optional<int> id = parseId(pos.at(0), &error);
    if (!id)
        return fail(error);
    plan.spec.id = *id;
    if (pos.at(1) == QLatin1String("speed"))
        plan.spec.loop = StepLoop::Speed;
    else if (pos.at(1) == QLatin1String("position"))
        plan.spec.loop = StepLoop::Position;
    else
        return fail(QStringLiteral("unknown loop '%1'; it is speed or position").arg(pos.at(1)));
    bool okFrom = false, okTo = false;
    plan.spec.from = pos.at(2).toDouble(&okFrom);
    plan.spec.to = pos.at(3).toDouble(&okTo);
    if (!okFrom || !okTo)
        return fail(QStringLiteral("FROM and TO must be numbers, got '%1' and '%2'")
                        .arg(pos.at(2), pos.at(3)));
    if (!readTiming(parser, plan.spec, &error))
        return fail(error);
    // The spec's own rules (durations, periods, FROM = TO) before the bus is touched.
    const QString bad = tuning::StepTestPlan::checkSpec(plan.spec);
    if (!bad.isEmpty())
        return fail(bad);
    const std::optional<MotionLimitOptions> limits = MotionLimitOptions::read(parser, &error);
    if (!limits)
        return fail(error);
    plan.limits = *limits;
    plan.json = parser.isSet(QStringLiteral("json"));
    return plan;
}

std::optional<QJsonObject> StepCommand::readGains(LiveBus &bus, int id,
                                                  const LiveBus::Identity &who) const
{
    QJsonObject gains;
    if (who.model.generation == protocol::Generation::V2_3) {
        const bus::RequestResult r = bus.request(protocol::Command::ReadPid, id);
        if (!r.ok() || !r.reply) {
            bus.reportFailure(r);
            return std::nullopt;
        }
        return protocol::FieldJson::replyFields(*r.reply);
    }
    // CAN V2.36 keeps them as control parameters (0xC0).
    if (bus.link() == protocol::Link::Can) {
        if (!ReadCommand::readCan236Params(bus, id, true, false, gains))
            return std::nullopt;
        return gains;
    }
    // V2.35 has no 0x30: the loops' gains (with Kd) come from the parameter table.
    for (const DriveParam &p : DriveParams::all()) {
        if (p.isLoop() && !DriveParams::readFields(bus, id, p, gains))
            return std::nullopt;
    }
    return gains;
}

StepTestResult StepCommand::runTest(LiveBus &bus, const Plan &plan,
                                    const safety::SoftLimits &limits, double gearRatio)
{
    tuning::StepTestRunner runner(bus.session());
    // The last request of this drive that failed: the runner says "did not answer" for any
    // failure, and a corrupt reply is an answer (the drive heard, and may have acted).
    QObject::connect(&bus.session(), &bus::BusSession::requestCompleted, &runner,
                     [&, id = plan.spec.id](const bus::RequestResult &r) {
                         if (r.request.id == id && !r.ok())
                             m_lastFailure = r;
                     });
    // Ctrl-C ends the test at once: no further setpoint; the output says what still moves.
    const int edges = plan.spec.periods == 1 ? 1 : 2 * plan.spec.periods;
    const double testS = plan.spec.preRollS + edges * plan.spec.durationS;
    return runToEnd<tuning::StepTestRunner, StepTestResult>(
        bus, runner, [&] { runner.start(plan.spec, limits, gearRatio); },
        int(testS * 1000) + LiveBus::kMaxWaitMs);
}

QString StepCommand::failureText(const StepTestResult &result) const
{
    if (result.failure != StepTestFailure::Silent || !m_lastFailure ||
        m_lastFailure->status != bus::RequestStatus::Error || m_lastFailure->reason.isEmpty())
        return result.message;
    // The drive answered, but its reply was corrupt (a bad checksum, as fw 2.35 drives send
    // now and then): say so, and that a motion command may have been acted on.
    const bus::RequestResult &r = *m_lastFailure;
    const bool motion = protocol::CommandTable::info(r.request.command).movesMotor;
    QString text = QStringLiteral("%1, sent %2 time(s): drive %3 answered, but not one reply "
                                  "was whole")
                       .arg(r.reason)
                       .arg(r.attempts)
                       .arg(r.request.id);
    if (motion)
        text += QStringLiteral("; it heard %1 and may have acted on it: it may be moving")
                    .arg(protocol::CommandTable::name(r.request.command));
    // The runner's own account of what the drive was last told follows its first clause.
    const QString rest = QStringLiteral(": the test stopped");
    const qsizetype at = result.message.indexOf(rest);
    return text + (at >= 0
                       ? QStringLiteral("; the test stopped") + result.message.mid(at + rest.size())
                       : QStringLiteral("; ") + result.message);
}

tuning::StepRun StepCommand::keptRun(const Plan &plan, const LiveBus::Identity &who,
                                     const QJsonObject &gains, const StepTestResult &result)
{
    tuning::StepRun run;
    run.number = 1;
    run.driveId = plan.spec.id;
    run.series = who.series ? protocol::seriesName(*who.series) : QString();
    run.model = who.model.motorName;
    run.generation = protocol::generationName(who.model.generation);
    run.spec = {plan.spec.loop, plan.spec.from, plan.spec.to, plan.spec.durationS,
                plan.spec.periods};
    run.gains = gains;
    run.effortLimit = tuning::seriesEffortLimit(who.series);
    run.trace = result.trace;
    run.ranAt = QDateTime::currentDateTimeUtc();
    return run;
}

int StepCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *o : {"duration", "periods", "pre-roll", "max-speed"})
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
    LiveBus::Identity who;
    const std::optional<safety::SoftLimits> limits =
        openDrive(bus, *busOptions, id, plan->limits, console, &status, &who);
    if (!limits)
        return status;
    const std::optional<QJsonObject> gains = readGains(bus, id, who);
    if (!gains) {
        bus.error(QStringLiteral("the gains could not be read; nothing was sent"));
        return kExitFailure;
    }
    const StepTestResult result = runTest(bus, *plan, *limits, who.gear());
    const auto refusal = [&] { bus.refused(text::VerdictText::stepRefusal(result.refusal)); };
    if (const auto failed =
            failureStatus(bus, console, result.failure, failureText(result), refusal))
        return *failed;
    const tuning::StepRun run = keptRun(*plan, who, *gains, result);
    if (plan->json)
        printJson(console, *plan, run, result);
    else
        printText(console, *plan, run, result);
    return kExitOk;
}

void StepCommand::printJson(Console &console, const Plan &plan, const tuning::StepRun &run,
                            const StepTestResult &r) const
{
    OrderedJson o;
    o.text(QStringLiteral("command"), QStringLiteral("step"))
        .integer(QStringLiteral("id"), plan.spec.id)
        .text(QStringLiteral("loop"), tuning::stepLoopWord(plan.spec.loop))
        .real(QStringLiteral("from"), plan.spec.from)
        .real(QStringLiteral("to"), plan.spec.to)
        .real(QStringLiteral("duration_s"), plan.spec.durationS)
        .integer(QStringLiteral("periods"), plan.spec.periods)
        .real(QStringLiteral("pre_roll_s"), plan.spec.preRollS);
    // The step under test (the first edge), as StepRunJson maps it, with the gains.
    const QJsonObject step = tuning::StepRunJson::toJson(run);
    addMetrics(o, step);
    o.fields(QStringLiteral("gains"), step.value(QStringLiteral("gains")).toObject())
        .raw(QStringLiteral("speed_bound"), MotionLimitOptions::boundJson(r.bound, r.boundDps))
        .raw(QStringLiteral("sent"), sentJson(r));
    QByteArray list = "[";
    for (const EdgeMetrics &m : run.metrics()) {
        OrderedJson e;
        e.real(QStringLiteral("time_s"), since(r, m.edge.time))
            .real(QStringLiteral("from"), m.edge.from)
            .real(QStringLiteral("to"), m.edge.to);
        addMetrics(e, tuning::StepRunJson::metricsObject(m, run.trace.effortIsPower));
        list += (list.size() > 1 ? "," : "") + e.toJson();
    }
    o.raw(QStringLiteral("edges"), list + ']');
    o.text(QStringLiteral("still_moving"), r.message);
    console.out(o.toJson() + '\n');
}

void StepCommand::printText(Console &console, const Plan &plan, const tuning::StepRun &run,
                            const StepTestResult &r) const
{
    const QString unit = unitOf(plan.spec.loop);
    const QVector<EdgeMetrics> edges = run.metrics();
    console.outLine(QStringLiteral("Step test on drive %1, %2 loop: %3 -> %4 %5, %6 of %7 s "
                                   "after a %8 s pre-roll at FROM.")
                        .arg(plan.spec.id)
                        .arg(plan.spec.loop == StepLoop::Speed ? QStringLiteral("speed")
                                                               : QStringLiteral("position"))
                        .arg(plan.spec.from)
                        .arg(plan.spec.to)
                        .arg(unit)
                        .arg(plan.spec.periods == 1
                                 ? QStringLiteral("one step")
                                 : QStringLiteral("%1 periods").arg(plan.spec.periods))
                        .arg(plan.spec.durationS)
                        .arg(plan.spec.preRollS));
    QStringList g;
    for (const QString &line : ReplyText::lines(run.gains))
        g << line.simplified();
    console.outLine(QStringLiteral("Gains: %1.").arg(g.join(QStringLiteral(", "))));
    console.outLine(QStringLiteral("Sent %1 setpoints (%2); %3 samples at %4 Hz.")
                        .arg(r.sent.size())
                        .arg(text::VerdictText::speedBound(r.bound, r.boundDps))
                        .arg(r.trace.size())
                        .arg(r.sampleRateHz, 0, 'f', 1));
    for (int i = 0; i < edges.size(); ++i) {
        const EdgeMetrics &m = edges.at(i);
        console.outLine(QStringLiteral("Edge %1 at %2 s: %3 -> %4 %5")
                            .arg(i + 1)
                            .arg(m.edge.time - originOf(r), 0, 'f', 3)
                            .arg(m.edge.from)
                            .arg(m.edge.to)
                            .arg(unit));
        for (const MetricRow &row : kRows)
            console.outLine(QStringLiteral("  %1 %2")
                                .arg(QLatin1String(row.label), -20)
                                .arg(metricText(m.*row.member, row.unit,
                                                row.unit == MetricRow::Value &&
                                                        row.member != &EdgeMetrics::oscillations
                                                    ? unit
                                                    : QString(),
                                                r.trace.effortIsPower)));
    }
    console.outLine(QStringLiteral("After the test: %1.").arg(r.message));
}

} // namespace lk::lkctl
