#include "ControlCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"

#include <safety/MotionGuard.h>

#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonParseError>

namespace lk::lkctl {

using protocol::FieldJson;

namespace {

/// MODE -> (command without max speed, command with it, the value's field).
struct Mode {
    const char *mode;
    const char *command;
    const char *limited; ///< nullptr: no --max-speed
    const char *field;
};

const Mode kModes[] = {
    {"open-loop", "open_loop", nullptr, "power"},
    {"torque", "torque", nullptr, "iq_a"},
    {"speed", "speed", nullptr, "speed_dps"},
    {"multi-position", "multi_position", "multi_position_limited", "angle_deg"},
    {"single-position", "single_position", "single_position_limited", "angle_deg"},
    {"increment", "increment_position", "increment_position_limited", "angle_deg"},
};

const Mode *findMode(const QString &name)
{
    for (const Mode &m : kModes) {
        if (name == QLatin1String(m.mode))
            return &m;
    }
    return nullptr;
}

QString modeList()
{
    QStringList names;
    for (const Mode &m : kModes)
        names << QLatin1String(m.mode);
    return names.join(QStringLiteral(", "));
}

} // namespace

QString ControlCommand::summary() const
{
    return QStringLiteral("send one motion command (torque, speed, position...) within limits");
}

QString ControlCommand::example() const
{
    return QStringLiteral("lkctl control 3 speed 360 --port /dev/ttyUSB0");
}

QString ControlCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl control ID MODE VALUE [MODE OPTIONS] [LIMITS] (--port DEV [--baud N] "
               "| --sim SPEC)\n"
               "                     [--json]\n"
               "\n"
               "Send one motion command to drive ID and print its reply (state 2). Values are\n"
               "rotor values in physical units, checked against the wire range first (a value\n"
               "out of range names the field and its range, exit 2), then against the drive's\n"
               "series (read with read_model) and your limits. A refused command sends NOTHING.\n"
               "\n"
               "MODE and VALUE:\n"
               "  open-loop POWER        open_loop, -1000..1000 (MS only)\n"
               "  torque IQ_A            torque current in A (MF, MG, MH)\n"
               "  speed DPS              speed in deg/s (negative: counter-clockwise)\n"
               "  multi-position DEG     multi-turn target angle in deg\n"
               "  single-position DEG    single-turn target 0..359.99 deg, needs --direction\n"
               "  increment DEG          move by DEG (sign gives the direction)\n"
               "Mode options:\n"
               "  --direction cw|ccw     single-position only\n"
               "  --max-speed DPS        position modes: limit the move's speed (the "
               "*_limited commands)\n"
               "Limits (defaults per series: a quarter of its rated current, open-loop power "
               "200,\n"
               "its top speed; positions unbounded):\n"
               "  --limits FILE.json     soft limits, e.g. {\"max_torque_a\":1.5,\"max_power\":"
               "300,\n"
               "                         \"max_speed_dps\":720,\"min_angle_deg\":-360,"
               "\"max_angle_deg\":360,\n"
               "                         \"max_increment_deg\":90} (missing keys keep the "
               "defaults)\n"
               "  --max-torque-a A, --max-speed-dps DPS, --max-power P\n"
               "                         override the defaults and the file\n"
               "  --json                 one line: {\"command\":\"speed\",\"id\":3,\"sent\":{...},"
               "\"reply\":{...}}\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl control 3 speed 360 --port /dev/ttyUSB0\n"
               "  lkctl control 3 torque -0.5 --port /dev/ttyUSB0 --max-torque-a 1\n"
               "  lkctl control 3 multi-position 720 --max-speed 180 --port ttyUSB0\n"
               "  lkctl control 3 single-position 90 --direction ccw --port ttyUSB0\n"
               "  lkctl control 3 increment -45 --limits bench-limits.json --port ttyUSB0\n"
               "  lkctl control 17 open-loop 150 --sim 17:MS\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  4  refused: the series or one of your limits does not allow it (the message\n"
                 "     names the limit and both values); nothing was sent\n")));
}

std::optional<protocol::FieldBuildResult> ControlCommand::build(const QStringList &pos,
                                                                const ArgParser &parser,
                                                                Console &console, int *status) const
{
    const Mode *mode = findMode(pos.at(1));
    if (!mode) {
        *status = usageError(
            console,
            QStringLiteral("unknown mode '%1'; MODE is one of %2").arg(pos.at(1), modeList()));
        return std::nullopt;
    }
    if (pos.size() != 3) {
        *status = usageError(console, QStringLiteral("%1 takes one value").arg(pos.at(1)));
        return std::nullopt;
    }
    const bool single = QLatin1String(mode->mode) == QLatin1String("single-position");
    const bool hasDirection = parser.isSet(QStringLiteral("direction"));
    const bool hasMaxSpeed = parser.isSet(QStringLiteral("max-speed"));
    QString problem;
    if (single != hasDirection)
        problem = single ? QStringLiteral("single-position needs --direction cw|ccw")
                         : QStringLiteral("--direction goes with single-position only");
    else if (hasMaxSpeed && !mode->limited)
        problem = QStringLiteral("--max-speed goes with the position modes only");
    if (!problem.isEmpty()) {
        *status = usageError(console, problem);
        return std::nullopt;
    }
    protocol::FieldValues values;
    values.insert(QStringLiteral("id"), pos.at(0));
    values.insert(QLatin1String(mode->field), pos.at(2));
    if (hasDirection)
        values.insert(QStringLiteral("direction"), parser.value(QStringLiteral("direction")));
    if (hasMaxSpeed)
        values.insert(QStringLiteral("max_speed_dps"), parser.value(QStringLiteral("max-speed")));
    const protocol::FieldBuildResult built =
        FieldJson::buildRequest(QLatin1String(hasMaxSpeed ? mode->limited : mode->command), values);
    if (!built.ok()) {
        *status = usageError(console, built.message);
        return std::nullopt;
    }
    return built;
}

bool ControlCommand::readLimitFlags(const ArgParser &parser, Plan &plan, Console &console,
                                    int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return false;
    };
    QString error;
    if (parser.isSet(QStringLiteral("max-torque-a"))) {
        plan.maxTorqueA = parser.numberValue(QStringLiteral("max-torque-a"), 0, &error);
        if (!plan.maxTorqueA)
            return fail(error);
    }
    if (parser.isSet(QStringLiteral("max-speed-dps"))) {
        plan.maxSpeedDps = parser.numberValue(QStringLiteral("max-speed-dps"), 0, &error);
        if (!plan.maxSpeedDps)
            return fail(error);
    }
    if (parser.isSet(QStringLiteral("max-power"))) {
        const auto p = parser.intValue(QStringLiteral("max-power"), 0, 1000, &error);
        if (!p)
            return fail(error);
        plan.maxPower = int(*p);
    }
    if (!parser.isSet(QStringLiteral("limits")))
        return true;
    const QString path = parser.value(QStringLiteral("limits"));
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("cannot read --limits %1: %2").arg(path, f.errorString()));
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &pe);
    if (!doc.isObject())
        return fail(QStringLiteral("--limits %1 is not a JSON object%2")
                        .arg(path, pe.error == QJsonParseError::NoError
                                       ? QString()
                                       : QStringLiteral(" (%1)").arg(pe.errorString())));
    // Check the file's values now, so that a bad file never gets as far as the bus.
    if (!safety::SoftLimits::fromJson(doc.object(), safety::SoftLimits{}, &error))
        return fail(QStringLiteral("--limits %1: %2").arg(path, error));
    plan.limitsJson = doc.object();
    return true;
}

std::optional<ControlCommand::Plan> ControlCommand::parse(const ArgParser &parser, Console &console,
                                                          int *status) const
{
    const QStringList &pos = parser.positionals();
    if (pos.size() < 3) {
        *status = usageError(console,
                             QStringLiteral("expected ID MODE VALUE (MODE: %1)").arg(modeList()));
        return std::nullopt;
    }
    const std::optional<protocol::FieldBuildResult> built = build(pos, parser, console, status);
    if (!built)
        return std::nullopt;
    Plan plan;
    plan.request = *built->request;
    plan.json = parser.isSet(QStringLiteral("json"));
    if (!readLimitFlags(parser, plan, console, status))
        return std::nullopt;
    return plan;
}

safety::SoftLimits ControlCommand::limitsFor(const Plan &plan,
                                             std::optional<protocol::Series> series) const
{
    safety::SoftLimits limits =
        series ? safety::SoftLimits::defaults(*series) : safety::SoftLimits{};
    if (plan.limitsJson) // already checked: cannot fail
        limits = safety::SoftLimits::fromJson(*plan.limitsJson, limits).value_or(limits);
    if (plan.maxTorqueA)
        limits.maxTorqueA = *plan.maxTorqueA;
    if (plan.maxSpeedDps)
        limits.maxSpeedDps = *plan.maxSpeedDps;
    if (plan.maxPower)
        limits.maxPower = *plan.maxPower;
    return limits;
}

int ControlCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *o :
         {"direction", "max-speed", "limits", "max-torque-a", "max-speed-dps", "max-power"})
        parser.addOption(QLatin1String(o), true);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    const int id = plan->request.id;

    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const std::optional<LiveBus::Identity> who = bus.identify(id);
    if (!who)
        return kExitFailure;
    const safety::Verdict verdict =
        safety::MotionGuard::check(plan->request, who->series, limitsFor(*plan, who->series));
    if (!verdict.allowed()) {
        bus.error(QStringLiteral("refused, nothing was sent: %1").arg(verdict.message));
        return kExitRefused;
    }
    const bus::RequestResult r = bus.request(plan->request);
    if (!r.ok() || !r.reply) {
        bus.reportFailure(r);
        if (r.status == bus::RequestStatus::Timeout)
            bus.error(QStringLiteral("the drive may have acted on it all the same: check "
                                     "with 'lkctl read %1 state2' or 'multi-turn'")
                          .arg(id));
        return kExitFailure;
    }
    const QJsonObject sent = FieldJson::requestFields(plan->request);
    const QJsonObject reply = FieldJson::replyFields(*r.reply);
    const QString command = protocol::CommandTable::name(plan->request.command);
    if (plan->json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), command)
            .integer(QStringLiteral("id"), id)
            .fields(QStringLiteral("sent"), sent)
            .fields(QStringLiteral("reply"), reply);
        console.out(o.toJson() + '\n');
        return kExitOk;
    }
    QStringList sentText;
    for (const QString &line : ReplyText::lines(sent))
        sentText << line.simplified();
    console.outLine(QStringLiteral("Sent %1 to drive %2: %3. Reply:")
                        .arg(command)
                        .arg(id)
                        .arg(sentText.join(QStringLiteral(", "))));
    for (const QString &line : ReplyText::lines(reply, QStringLiteral("  ")))
        console.outLine(line);
    return kExitOk;
}

} // namespace lk::lkctl
