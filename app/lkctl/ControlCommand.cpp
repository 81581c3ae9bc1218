#include "ControlCommand.h"

#include "Console.h"
#include "ControlWatch.h"
#include "LiveBus.h"
#include "MotionLimitOptions.h"
#include "MultiTorqueControl.h"
#include "OrderedJson.h"
#include "ReplyText.h"

#include <protocol/CanLayout.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionPlanner.h>
#include <text/VerdictText.h>

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

/// The fields of `request` as sent to `drive`. On CAN a max speed goes out as a uint16 of
/// 1 dps, rounded down (docs/CAN.md section 6): max_speed_raw is that number, the one on the
/// wire, not RS485's 0.01 dps.
QJsonObject sentFields(const protocol::Request &request, const protocol::DecodeContext &drive)
{
    QJsonObject sent = FieldJson::requestFields(request, drive);
    if (!drive.onCan() || !sent.contains(QStringLiteral("max_speed_raw")))
        return sent;
    const protocol::can::CanEncodeResult e = protocol::can::encodeRequest(request, drive);
    if (e.ok()) {
        const QByteArray &b = e.data->bytes; // B2-B3: the max speed, little-endian
        sent.insert(QStringLiteral("max_speed_raw"),
                    int(quint8(b.at(2))) | (int(quint8(b.at(3))) << 8));
    }
    return sent;
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
               "       lkctl control multi-torque ID=IQ_A[,ID=IQ_A...] [LIMITS] --can PLUGIN:IF\n"
               "                     --drives LIST [--watch SECONDS] [--json]\n"
               "\n"
               "Send one motion command to drive ID and print its reply (state 2). Values are\n"
               "rotor values in physical units, checked against the wire range first (a value\n"
               "out of range names the field and its range, exit 2), then against the drive's\n"
               "series (read with read_model) and your limits. A refused command sends NOTHING.\n"
               "\n"
               "Every move is bounded by the speed limit: a position move without --max-speed\n"
               "is sent as its limited form (multi_position_limited, single_position_limited,\n"
               "increment_position_limited) with max speed = your speed limit (or the series\n"
               "top speed if that is lower); the output says which speed bound applied.\n"
               "A multi-position target is checked against the drive's multi-turn angle, read\n"
               "first (0x92): it may lie at most one output turn away (360 deg x the gear ratio\n"
               "of the motor name, e.g. -i10: 3600 rotor deg) and inside your angle range. An\n"
               "increment may be at most one output turn (with an angle range set, the angle\n"
               "is read and the end point checked too).\n"
               "A torque is sent at the drive's own scale (V2.35 MF 33/4096 A, MG 66/4096 A\n"
               "per LSB; V2.3 32/2000 A). On a V2.35 drive (firmware 2.35) the motor state\n"
               "(read_state1) and the brake (brake read) are read first: a drive that is off\n"
               "is refused (Motor On first: lkctl run ID; a control command does not turn it\n"
               "on), and an engaged brake is a warning (the shaft is held). Its own limits\n"
               "(read_param: Max Speed, max torque current or Max Power, Max Angle) bound the\n"
               "command where they are lower than yours, and a refusal or speed bound says\n"
               "so (speed_bound source drive_max_speed).\n"
               "\n"
               "MODE and VALUE:\n"
               "  open-loop POWER        open_loop, -850..850 (MS only; V2.35 narrowed V2.3's "
               "1000)\n"
               "  torque IQ_A            torque current in A (MF, MG, MH)\n"
               "  speed DPS              speed in deg/s (negative: counter-clockwise)\n"
               "  multi-position DEG     multi-turn target angle in deg (absolute)\n"
               "  single-position DEG    single-turn target 0..359.99 deg, needs --direction\n"
               "  increment DEG          move by DEG (sign gives the direction)\n"
               "%5"
               "Mode options:\n"
               "  --direction cw|ccw     single-position only\n"
               "  --max-speed DPS        position modes: a lower max speed for this move (above\n"
               "                         your speed limit is refused)\n"
               "%2"
               "%4"
               "  --json                 one line: {\"command\":\"speed\",\"id\":3,\"sent\":{...},"
               "\n"
               "                         \"speed_bound\":{\"source\":\"soft_limit\",\"dps\":720},"
               "\"reply\":{...}}\n"
               "                         (source: command, soft_limit, series_top, max_speed or\n"
               "                         drive_max_speed (a V2.35 drive's own Max Speed); no\n"
               "                         speed_bound for torque and open loop)\n"
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
               "  lkctl control multi-torque 1=0.5,2=-0.5 --watch 5 --can socketcan:can0 \\\n"
               "        --drives 1:MG@can,2:MG@can\n"
               "\n"
               "%3")
        .arg(BusOptions::helpText(), MotionLimitOptions::helpText(),
             exitStatusText(
                 QStringLiteral(
                     "  4  refused for safety: the series or one of your limits does not allow it\n"
                     "     (the message names the limit and both values), or a V2.35 drive is\n"
                     "     off; nothing was sent\n") +
                 ControlWatch::exitStatusLine()),
             ControlWatch::helpText(), MultiTorqueControl::helpText());
}

std::optional<FieldBuildResult> ControlCommand::build(const QStringList &pos,
                                                      const ArgParser &parser, Console &console,
                                                      int *status, Plan &plan) const
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
    FieldValues values;
    values.insert(QStringLiteral("id"), pos.at(0));
    values.insert(QLatin1String(mode->field), pos.at(2));
    if (hasDirection)
        values.insert(QStringLiteral("direction"), parser.value(QStringLiteral("direction")));
    if (hasMaxSpeed)
        values.insert(QStringLiteral("max_speed_dps"), parser.value(QStringLiteral("max-speed")));
    plan.command = QLatin1String(hasMaxSpeed ? mode->limited : mode->command);
    plan.values = values;
    const FieldBuildResult built = RequestText::build(plan.command, values);
    if (!built.ok()) {
        *status = usageError(console, built.message);
        return std::nullopt;
    }
    return built;
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
    Plan plan;
    const std::optional<FieldBuildResult> built = build(pos, parser, console, status, plan);
    if (!built)
        return std::nullopt;
    plan.request = *built->request;
    plan.json = parser.isSet(QStringLiteral("json"));
    QString error;
    const std::optional<MotionLimitOptions> limits = MotionLimitOptions::read(parser, &error);
    if (!limits) {
        *status = usageError(console, error);
        return std::nullopt;
    }
    plan.limits = *limits;
    return plan;
}

bool ControlCommand::readPosition(LiveBus &bus, const Plan &plan, const LiveBus::Identity &who,
                                  const safety::SoftLimits &limits,
                                  safety::DrivePosition &position) const
{
    position.gearRatio = who.gear();
    if (!safety::MotionPlanner::needsAngle(plan.request, limits))
        return true;
    // Targets start where the drive is: never judge a move from an assumed 0.
    const bus::RequestResult r = bus.request(protocol::Command::ReadMultiTurn, plan.request.id);
    const auto *angle =
        r.ok() && r.reply ? std::get_if<protocol::MultiTurnAngle>(&r.reply->payload) : nullptr;
    if (!angle) {
        bus.reportFailure(r);
        bus.error(QStringLiteral("the move needs the drive's current angle; nothing was sent"));
        return false;
    }
    position.angleDeg = angle->degrees();
    return true;
}

safety::DriveLimits ControlCommand::readDriveLimits(LiveBus &bus, int id,
                                                    const protocol::DecodeContext &drive) const
{
    QList<protocol::ParameterValue> values;
    for (protocol::ParamId param : safety::DriveLimits::params()) {
        const bus::RequestResult r = bus.request(*protocol::build::readParam(id, param).request);
        if (const auto *v = r.ok() && r.reply
                                ? std::get_if<protocol::ParameterValue>(&r.reply->payload)
                                : nullptr)
            values.append(*v);
    }
    return safety::DriveLimits::fromParams(values, drive);
}

bool ControlCommand::checkDriveState(LiveBus &bus, int id, int *status) const
{
    const bus::RequestResult r = bus.request(protocol::Command::ReadState1, id);
    const auto *state =
        r.ok() && r.reply ? std::get_if<protocol::State1>(&r.reply->payload) : nullptr;
    if (!state) {
        bus.reportFailure(r);
        bus.error(QStringLiteral("whether the motor of drive %1 is on is unknown (read_state1 "
                                 "failed); nothing was sent")
                      .arg(id));
        *status = kExitFailure;
        return false;
    }
    const std::optional<bool> on = state->motorOn();
    if (!on.value_or(false)) {
        bus.refused(QStringLiteral("drive %1 is %2: Motor On first with 'lkctl run %1' "
                                   "(motor_run, 0x88). A V2.35 drive stays off after motor_off "
                                   "or a protection trip, and a control command does not turn "
                                   "it on.")
                        .arg(id)
                        .arg(on ? QStringLiteral("off")
                                : QStringLiteral("in an undocumented motor state (0x%1)")
                                      .arg(state->motorStateRaw, 2, 16, QLatin1Char('0'))));
        *status = kExitRefused;
        return false;
    }
    const bus::RequestResult b =
        bus.request(*protocol::build::brake(id, protocol::BrakeAction::Read).request);
    const auto *brake =
        b.ok() && b.reply ? std::get_if<protocol::BrakeState>(&b.reply->payload) : nullptr;
    if (!brake)
        bus.error(QStringLiteral("warning: the brake of drive %1 could not be read: if it is "
                                 "engaged, the shaft is held and will not move")
                      .arg(id));
    else if (!brake->released())
        bus.error(QStringLiteral("warning: the brake of drive %1 reads engaged: the shaft is "
                                 "held and will not move until it is released ('lkctl brake %1 "
                                 "release --yes')")
                      .arg(id));
    return true;
}

int ControlCommand::send(LiveBus &bus, const Plan &plan, const safety::MotionPlan &motion,
                         const safety::DrivePosition &position,
                         const protocol::DecodeContext &drive) const
{
    const protocol::Request &request = *motion.request;
    const int id = request.id;
    const bus::RequestResult r = bus.request(request);
    if (!r.ok() || !r.reply) {
        bus.reportFailure(r);
        // Sent but not answered cleanly (silence, or a corrupt reply such as fw 2.35's bad
        // data checksum on 0xA4): the drive may be moving all the same.
        const bool sent = r.attempts > 0 && (r.status == bus::RequestStatus::Timeout ||
                                             r.status == bus::RequestStatus::Error);
        if (sent)
            bus.error(QStringLiteral("the command was sent %1 time(s) and the drive may have "
                                     "acted on it all the same (it may be moving): check with "
                                     "'lkctl read %2 state2' or 'multi-turn', or stop it with "
                                     "'lkctl stop %2'")
                          .arg(r.attempts)
                          .arg(id));
        return kExitFailure;
    }
    const QJsonObject sent = sentFields(request, drive);
    const QJsonObject reply = FieldJson::replyFields(*r.reply);
    const QString command = protocol::CommandTable::name(request.command);
    if (plan.json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), command)
            .integer(QStringLiteral("id"), id)
            .fields(QStringLiteral("sent"), sent);
        if (motion.drivesOwnSpeed)
            o.raw(QStringLiteral("speed_bound"),
                  QByteArray("{\"source\":\"drive_max_speed\",\"dps\":") +
                      QByteArray::number(motion.boundDps, 'g', 10) + '}');
        else if (motion.bound != safety::SpeedBound::None)
            o.raw(QStringLiteral("speed_bound"),
                  MotionLimitOptions::boundJson(motion.bound, motion.boundDps));
        o.fields(QStringLiteral("reply"), reply);
        bus.console().out(o.toJson() + '\n');
        return kExitOk;
    }
    QStringList sentText;
    for (const QString &line : ReplyText::lines(sent))
        sentText << line.simplified();
    QString extra;
    if (motion.bound != safety::SpeedBound::None)
        extra += QStringLiteral(" Speed bound: %1.")
                     .arg(motion.drivesOwnSpeed
                              ? safety::DriveLimits::speedBound(motion.bound, motion.boundDps)
                              : text::VerdictText::speedBound(motion.bound, motion.boundDps));
    if (position.angleDeg)
        extra += QStringLiteral(" The drive was at %1 deg.").arg(*position.angleDeg);
    bus.console().outLine(QStringLiteral("Sent %1 to drive %2: %3.%4 Reply:")
                              .arg(command)
                              .arg(id)
                              .arg(sentText.join(QStringLiteral(", ")), extra));
    for (const QString &line : ReplyText::lines(reply, QStringLiteral("  ")))
        bus.console().outLine(line);
    return kExitOk;
}

int ControlCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *o : {"direction", "max-speed"})
        parser.addOption(QLatin1String(o), true);
    MotionLimitOptions::declare(parser);
    ControlWatch::declare(parser);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    if (parser.positionals().value(0) == QLatin1String(MultiTorqueControl::kMode))
        return MultiTorqueControl::run(parser, *busOptions, console, name());
    const std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    QString watchError; // --watch: the speed watch after torque and open loop (ControlWatch)
    std::optional<ControlWatch> watch = ControlWatch::read(parser, &watchError);
    if (!watch)
        return usageError(console, watchError);

    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const std::optional<LiveBus::Identity> who = bus.identify(plan->request.id);
    if (!who)
        return kExitFailure;
    return runFor(bus, *plan, *who, *watch);
}

int ControlCommand::runFor(LiveBus &bus, Plan plan, const LiveBus::Identity &who,
                           ControlWatch &watch) const
{
    // A torque is in the drive's own units (V2.35 MF and MG differ from V2.3): built again
    // now that the drive is known.
    const protocol::DecodeContext drive{who.series.value_or(protocol::Series::MF),
                                        who.model.generation, bus.link()};
    const FieldBuildResult rebuilt = RequestText::build(plan.command, plan.values, drive);
    if (!rebuilt.ok())
        return usageError(bus.console(), rebuilt.message);
    plan.request = *rebuilt.request;
    QString error;
    const std::optional<safety::SoftLimits> limits = plan.limits.limitsFor(who.series, &error);
    if (!limits)
        return usageError(bus.console(), error);
    safety::DrivePosition position;
    if (!readPosition(bus, plan, who, *limits, position))
        return kExitFailure;
    // Each bound is the lower of the soft limit and the drive's own, where it holds one.
    // RS485 V2.35 holds its own limits in parameters (0x40); CAN V2.36 has only 0xC0/0xC1.
    const bool v235 =
        who.model.generation == protocol::Generation::V2_35 && bus.link() == protocol::Link::Rs485;
    const safety::DriveLimits own =
        v235 ? readDriveLimits(bus, plan.request.id, drive) : safety::DriveLimits{};
    const safety::MotionPlan motion =
        safety::MotionPlanner::plan(plan.request, who.series, *limits, position, own);
    if (!motion.allowed()) {
        bus.refused(motion.verdict.drivesOwn
                        ? safety::DriveLimits::refusal(motion.verdict)
                        : text::VerdictText::verdict(motion.verdict, who.series));
        return kExitRefused;
    }
    int status = kExitOk;
    if (v235 && !checkDriveState(bus, plan.request.id, &status))
        return status;
    watch.arm(bus, plan.request.id, *limits);
    return watch.follow(bus, *motion.request, plan.json, send(bus, plan, motion, position, drive));
}

} // namespace lk::lkctl
