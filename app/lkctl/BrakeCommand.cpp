#include "BrakeCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"

#include <protocol/RequestBuilder.h>

namespace lk::lkctl {

using protocol::BrakeAction;

namespace {

std::optional<BrakeAction> actionFor(const QString &word)
{
    if (word == QLatin1String("status"))
        return BrakeAction::Read;
    if (word == QLatin1String("engage"))
        return BrakeAction::Engage;
    if (word == QLatin1String("release"))
        return BrakeAction::Release;
    return std::nullopt;
}

QString actionWord(BrakeAction action)
{
    switch (action) {
    case BrakeAction::Engage:
        return QStringLiteral("engage");
    case BrakeAction::Release:
        return QStringLiteral("release");
    case BrakeAction::Read:
        break;
    }
    return QStringLiteral("status");
}

} // namespace

QString BrakeCommand::summary() const
{
    return QStringLiteral("read, engage or release a V2.35 drive's holding brake");
}

QString BrakeCommand::example() const
{
    return QStringLiteral("lkctl brake 1 status --port /dev/ttyUSB0");
}

QString BrakeCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl brake ID status|engage|release [--yes] [--motor-off-ok]\n"
               "                   (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "The holding brake of drive ID (brake, 0x8C; firmware 2.35 and later, protocol\n"
               "V2.35; a V2.3 drive is refused after read_model, exit 1). status only reads it;\n"
               "engage powers it off (the brake holds); release powers it (the shaft is free).\n"
               "The drive answers with the brake's state, which is printed.\n"
               "\n"
               "Releasing drops whatever the brake holds on a vertical axis unless the motor\n"
               "holds it. So release needs --yes, and the motor state is read first\n"
               "(read_state1): while the motor is off (or its state is not one of the two\n"
               "documented codes) release is refused unless --motor-off-ok is given too.\n"
               "\n"
               "Options:\n"
               "  --yes            confirm a release\n"
               "  --motor-off-ok   release even though the motor is off (the axis cannot fall)\n"
               "  --json           one line: "
               "{\"command\":\"brake\",\"id\":1,\"action\":\"release\","
               "\"motor_on\":true,\n"
               "                   \"brake_released\":true,\"brake_raw\":1} (motor_on: null "
               "unless\n"
               "                   release read it)\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl brake 1 status --port /dev/ttyUSB0\n"
               "  lkctl brake 1 engage --port /dev/ttyUSB0 --json\n"
               "  lkctl brake 1 release --yes --port /dev/ttyUSB0\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  4  refused: release without --yes, or with the motor off without\n"
                 "     --motor-off-ok (nothing was sent to the brake)\n"
                 "  5  the brake's reply says another state than the one asked for\n"
                 "  (1 also: the drive runs protocol V2.3, which has no brake command)\n")));
}

int BrakeCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    parser.addOption(QStringLiteral("yes"), false);
    parser.addOption(QStringLiteral("motor-off-ok"), false);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const QStringList &pos = parser.positionals();
    if (pos.size() != 2)
        return usageError(console, pos.size() < 2
                                       ? QStringLiteral("expected ID and status|engage|release")
                                       : QStringLiteral("unexpected argument '%1'").arg(pos.at(2)));
    QString error;
    const std::optional<int> id = parseId(pos.at(0), &error);
    if (!id)
        return usageError(console, error);
    const std::optional<BrakeAction> action = actionFor(pos.at(1));
    if (!action)
        return usageError(console, QStringLiteral("cannot '%1' a brake; say status, engage or "
                                                  "release")
                                       .arg(pos.at(1)));
    const bool release = *action == BrakeAction::Release;
    if (!release &&
        (parser.isSet(QStringLiteral("yes")) || parser.isSet(QStringLiteral("motor-off-ok"))))
        return usageError(console, QStringLiteral("--yes and --motor-off-ok go with release only"));
    if (release && !parser.isSet(QStringLiteral("yes"))) {
        console.errLine(
            QStringLiteral(
                "lkctl brake: refusing to release the brake of drive %1 without --yes: a load the "
                "brake holds (a vertical axis) drops unless the motor holds it; nothing was sent. "
                "Make sure the axis cannot fall, then add --yes.")
                .arg(*id));
        return kExitRefused;
    }
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const std::optional<LiveBus::Identity> who = bus.identify(*id);
    if (!who)
        return kExitFailure;
    if (who->model.generation != protocol::Generation::V2_35 && bus.link() == protocol::Link::Can) {
        bus.error(QStringLiteral("drive %1 speaks CAN (old), which has no brake command (0x8C); "
                                 "nothing was sent")
                      .arg(*id));
        return kExitFailure;
    }
    if (who->model.generation != protocol::Generation::V2_35) {
        bus.error(QStringLiteral("drive %1 runs firmware before 2.35 (protocol V2.3), which has no "
                                 "brake command (0x8C); nothing was sent. A V2.3 drive's brake, "
                                 "if it has one, is not controlled over RS485.")
                      .arg(*id));
        return kExitFailure;
    }
    std::optional<bool> motorOn;
    if (release) {
        const auto checked =
            checkRelease(bus, *id, parser.isSet(QStringLiteral("motor-off-ok")), &status);
        if (!checked)
            return status;
        motorOn = *checked;
    }
    return finish(bus, *id, *action, motorOn, parser.isSet(QStringLiteral("json")));
}

std::optional<std::optional<bool>> BrakeCommand::checkRelease(LiveBus &bus, int id, bool motorOffOk,
                                                              int *status) const
{
    const bus::RequestResult r = bus.request(protocol::Command::ReadState1, id);
    const auto *state = r.reply ? std::get_if<protocol::State1>(&r.reply->payload) : nullptr;
    if (!r.ok() || !state) {
        bus.reportFailure(r);
        bus.error(QStringLiteral("the motor state of drive %1 is unknown, so the brake was not "
                                 "released; nothing was sent to it")
                      .arg(id));
        *status = kExitFailure;
        return std::nullopt;
    }
    const std::optional<bool> on = state->motorOn();
    if (on.value_or(false) || motorOffOk)
        return on;
    bus.error(QStringLiteral("refusing to release the brake of drive %1: the motor is %2, so "
                             "nothing holds the load once the brake lets go (a vertical axis "
                             "drops); nothing was sent. Turn the motor on first with 'lkctl "
                             "run %1' (motor_run, 0x88: a control command does not turn a "
                             "V2.35 drive on), or add --motor-off-ok if the axis cannot fall.")
                  .arg(id)
                  .arg(on ? QStringLiteral("off")
                          : QStringLiteral("in an undocumented state (0x%1)")
                                .arg(state->motorStateRaw, 2, 16, QLatin1Char('0'))));
    *status = kExitRefused;
    return std::nullopt;
}

int BrakeCommand::finish(LiveBus &bus, int id, BrakeAction action, std::optional<bool> motorOn,
                         bool json)
{
    const bus::RequestResult r = bus.request(*protocol::build::brake(id, action).request);
    const auto *brake = r.reply ? std::get_if<protocol::BrakeState>(&r.reply->payload) : nullptr;
    if (!r.ok() || !brake) {
        bus.reportFailure(r);
        return kExitFailure;
    }
    Console &console = bus.console();
    if (json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), QStringLiteral("brake"))
            .integer(QStringLiteral("id"), id)
            .text(QStringLiteral("action"), actionWord(action));
        if (motorOn)
            o.boolean(QStringLiteral("motor_on"), *motorOn);
        else
            o.null(QStringLiteral("motor_on"));
        o.boolean(QStringLiteral("brake_released"), brake->released())
            .integer(QStringLiteral("brake_raw"), brake->raw);
        console.out(o.toJson() + '\n');
    } else {
        console.outLine(QStringLiteral("Drive %1: brake %2%3")
                            .arg(id)
                            .arg(brake->released() ? QStringLiteral("released (shaft free)")
                                                   : QStringLiteral("engaged (holding)"))
                            .arg(motorOn ? (*motorOn ? QStringLiteral(", motor on")
                                                     : QStringLiteral(", motor off"))
                                         : QString()));
    }
    if (action == BrakeAction::Read || brake->released() == (action == BrakeAction::Release))
        return kExitOk;
    bus.error(QStringLiteral("drive %1 was asked to %2 its brake but reports it %3")
                  .arg(id)
                  .arg(actionWord(action),
                       brake->released() ? QStringLiteral("released") : QStringLiteral("engaged")));
    return kExitMismatch;
}

} // namespace lk::lkctl
