#include "MotorStateCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"

#include <safety/MotionGuard.h>
#include <text/VerdictText.h>

namespace lk::lkctl {

using protocol::Command;

namespace {
QByteArray idArray(const QVector<int> &ids)
{
    QByteArray out = "[";
    for (qsizetype i = 0; i < ids.size(); ++i)
        out += (i > 0 ? "," : "") + QByteArray::number(ids.at(i));
    return out + "]";
}

QString idText(const QVector<int> &ids)
{
    QStringList t;
    for (int id : ids)
        t << QString::number(id);
    return t.isEmpty() ? QStringLiteral("none") : t.join(QStringLiteral(", "));
}
} // namespace

MotorStateCommand::MotorStateCommand(Command command) : m_command(command) {}

QString MotorStateCommand::name() const
{
    switch (m_command) {
    case Command::MotorOff:
        return QStringLiteral("off");
    case Command::MotorStop:
        return QStringLiteral("stop");
    default:
        return QStringLiteral("run");
    }
}

QString MotorStateCommand::summary() const
{
    switch (m_command) {
    case Command::MotorOff:
        return QStringLiteral("motor off (clears the command); 'off all' is the emergency stop");
    case Command::MotorStop:
        return QStringLiteral("motor stop (keeps the command; 'run' resumes it)");
    default:
        return QStringLiteral("motor run: resume after a stop (V2.3); Motor On (V2.35)");
    }
}

QString MotorStateCommand::example() const
{
    return QStringLiteral("lkctl %1 %2 --port /dev/ttyUSB0")
        .arg(name(), m_command == Command::MotorOff ? QStringLiteral("all") : QStringLiteral("3"));
}

QString MotorStateCommand::usage() const
{
    const QString what =
        m_command == Command::MotorOff
            ? QStringLiteral(
                  "Send motor_off (0x80) to drive ID: the motor is released and its running\n"
                  "state and pending command are cleared.\n"
                  "'off all' is the emergency stop: motor_off to every ID 1..32 ahead of\n"
                  "anything else, each ID first with a short timeout so that every drive hears\n"
                  "it quickly, then the silent ones again.\n")
        : m_command == Command::MotorStop
            ? QStringLiteral("Send motor_stop (0x81) to drive ID: the motor stops and keeps its\n"
                             "running state and command; 'lkctl run' resumes it.\n"
                             "'stop all' sends motor_stop to every ID 1..32 ahead of anything\n"
                             "else, like 'off all'.\n")
            : QStringLiteral("Send motor_run (0x88) to drive ID. A V2.3 drive resumes the "
                             "command it held\nwhen stopped. A V2.35 drive (firmware 2.35) "
                             "turns its motor on after motor_off\nor a protection trip: it "
                             "stays off until then, whatever control command comes,\nand holds "
                             "no command (a stop is left by a new control command). The\ndrive's "
                             "series is read first and checked like any motion command.\n'run "
                             "all' sends it to every drive a scan finds, and sends nothing if\n"
                             "any of them refuses.\n");
    return QStringLiteral("Usage: lkctl %1 ID|all (--port DEV [--baud N] | --sim SPEC) [--json]\n"
                          "\n"
                          "%2"
                          "\n"
                          "Options:\n"
                          "  --json   one line: {\"command\":\"%3\",\"acknowledged\":[3,17],"
                          "\"silent\":[]}\n"
                          "\n"
                          "%4"
                          "\n"
                          "Examples:\n"
                          "  lkctl %1 3 --port /dev/ttyUSB0\n"
                          "  lkctl %1 all --port ttyUSB0 --baud 1000000\n"
                          "\n"
                          "%5")
        .arg(name(), what, protocol::CommandTable::name(m_command), BusOptions::helpText(),
             exitStatusText(
                 QStringLiteral("  With 'all', 0 means at least one drive acknowledged and none "
                                "that was\n  found stayed silent%1.\n")
                     .arg(m_command != Command::MotorRun
                              ? QStringLiteral(" (IDs without a drive stay silent, which is "
                                               "expected)")
                              : QString())) +
                 (m_command == Command::MotorRun
                      ? QStringLiteral("  4  refused: the drive's series does not allow it "
                                       "(nothing was sent)\n")
                      : QString()));
}

void MotorStateCommand::print(Console &console, bool json, const QVector<int> &acknowledged,
                              const QVector<int> &silent) const
{
    if (json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), protocol::CommandTable::name(m_command))
            .raw(QStringLiteral("acknowledged"), idArray(acknowledged))
            .raw(QStringLiteral("silent"), idArray(silent));
        console.out(o.toJson() + '\n');
        return;
    }
    console.outLine(QStringLiteral("%1 acknowledged by: %2")
                        .arg(protocol::CommandTable::name(m_command), idText(acknowledged)));
    if (!silent.isEmpty())
        console.outLine(QStringLiteral("silent: %1").arg(idText(silent)));
}

bool MotorStateCommand::allowed(LiveBus &bus, int id, std::optional<protocol::Series> series)
{
    if (m_command != Command::MotorRun)
        return true;
    protocol::Request r;
    r.command = m_command;
    r.id = quint8(id);
    const safety::Verdict v =
        safety::MotionGuard::check(r, series, safety::SoftLimits::defaults(series));
    if (!v.allowed())
        bus.refused(text::VerdictText::verdict(v, series), id);
    return v.allowed();
}

int MotorStateCommand::runOne(LiveBus &bus, int id, bool json)
{
    if (m_command == Command::MotorRun) {
        const std::optional<LiveBus::Identity> who = bus.identify(id);
        if (!who)
            return kExitFailure;
        if (!allowed(bus, id, who->series))
            return kExitRefused;
    }
    // off and stop take the emergency lane: they go ahead of anything queued.
    const bus::Priority p =
        m_command == Command::MotorRun ? bus::Priority::Operator : bus::Priority::Emergency;
    const bus::RequestResult r = bus.request(m_command, id, p);
    if (!r.ok()) {
        bus.reportFailure(r);
        return kExitFailure;
    }
    print(bus.console(), json, {id}, {});
    return kExitOk;
}

int MotorStateCommand::runAll(LiveBus &bus, bool json)
{
    if (m_command != Command::MotorRun) {
        // off and stop go to every ID 1..32 in the emergency lane, not to the drives a scan
        // happened to hear: a drive missed on a slow link must still stop.
        const LiveBus::StopOutcome o = bus.emergencyStop({}, m_command);
        print(bus.console(), json, o.acknowledged, o.silent);
        // The JSON keeps CLI.md's shape (they are silent too); a person is told the truth.
        if (!o.unsent.isEmpty())
            bus.error(QStringLiteral("%1 never went out to %2: the link was lost; they may still "
                                     "be moving")
                          .arg(protocol::CommandTable::name(m_command), idText(o.unsent)));
        return o.acknowledged.isEmpty() ? kExitFailure : kExitOk;
    }
    bus::ScanOptions options;
    options.retries = 1; // a drive missed here would silently stay stopped
    const bus::ScanSummary s = bus.scan(options);
    if (!s.error.isEmpty()) {
        bus.error(QStringLiteral("scan stopped: %1").arg(s.error));
        return kExitFailure;
    }
    if (s.motors.isEmpty()) {
        bus.error(QStringLiteral("no drive answered the scan; nothing was sent"));
        return kExitFailure;
    }
    // Every drive is checked before any is sent motor_run: a refusal sends nothing at all.
    bool refused = false;
    for (const bus::FoundMotor &m : s.motors)
        refused = !allowed(bus, m.id, m.series) || refused;
    if (refused)
        return kExitRefused;
    QVector<int> acked, silent;
    for (const bus::FoundMotor &m : s.motors) {
        const bus::RequestResult r = bus.request(m_command, m.id);
        (r.ok() ? acked : silent).append(m.id);
    }
    print(bus.console(), json, acked, silent);
    return silent.isEmpty() ? kExitOk : kExitFailure;
}

int MotorStateCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const QStringList &pos = parser.positionals();
    if (pos.size() != 1)
        return usageError(console, pos.isEmpty() ? QStringLiteral("missing ID or 'all'")
                                                 : QStringLiteral("expected one ID or 'all'"));
    const bool all = pos.first() == QLatin1String("all");
    QString error;
    const std::optional<int> id = all ? std::optional<int>(0) : parseId(pos.first(), &error);
    if (!id)
        return usageError(console, error + QStringLiteral(", or 'all'"));
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const bool json = parser.isSet(QStringLiteral("json"));
    return all ? runAll(bus, json) : runOne(bus, *id, json);
}

} // namespace lk::lkctl
