#include "ReadCommand.h"

#include "Console.h"
#include "DriveParams.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"

#include <motor/SeriesLimits.h>
#include <protocol/ControlParameter.h>
#include <protocol/FieldJson.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QList>

namespace lk::lkctl {

using protocol::Command;

namespace {
const QList<QPair<QString, Command>> &whats()
{
    static const QList<QPair<QString, Command>> kWhats{
        {QStringLiteral("pid"), Command::ReadPid},
        {QStringLiteral("accel"), Command::ReadAccel},
        {QStringLiteral("encoder"), Command::ReadEncoder},
        {QStringLiteral("multi-turn"), Command::ReadMultiTurn},
        {QStringLiteral("single-turn"), Command::ReadSingleTurn},
        {QStringLiteral("state1"), Command::ReadState1},
        {QStringLiteral("state2"), Command::ReadState2},
        {QStringLiteral("state3"), Command::ReadState3},
        {QStringLiteral("model"), Command::ReadModel},
        {QStringLiteral("params"), Command::ReadParam},
    };
    return kWhats;
}

QString whatList()
{
    QStringList names;
    for (const auto &w : whats())
        names << w.first;
    return names.join(QStringLiteral(", "));
}
} // namespace

std::optional<Command> ReadCommand::commandFor(const QString &what)
{
    for (const auto &w : whats()) {
        if (w.first == what)
            return w.second;
    }
    return std::nullopt;
}

QString ReadCommand::summary() const
{
    return QStringLiteral("read one value set from a drive (pid, accel, encoder, angles, state)");
}

QString ReadCommand::example() const
{
    return QStringLiteral("lkctl read 3 state2 --port /dev/ttyUSB0 --json");
}

QString ReadCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl read ID WHAT (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "Send one read command to drive ID and print the reply.\n"
               "\n"
               "WHAT      command           fields (CLI.md)\n"
               "  pid          read_pid          angle_kp angle_ki speed_kp speed_ki iq_kp "
               "iq_ki\n"
               "  accel        read_accel        accel_dps2\n"
               "  encoder      read_encoder      encoder encoder_raw encoder_offset\n"
               "  multi-turn   read_multi_turn   angle_deg (rotor, 0.01 deg)\n"
               "  single-turn  read_single_turn  angle_deg\n"
               "  state1       read_state1       temperature_c voltage_v error_state "
               "low_voltage over_temperature\n"
               "  state2       read_state2       temperature_c iq_a (power on MS) speed_dps "
               "encoder\n"
               "  state3       read_state3       temperature_c ia_a ib_a ic_a (not on MS)\n"
               "  model        read_model        driver_name motor_name hardware_version "
               "firmware_version\n"
               "  params       read_param        V2.35 only: angle_kp angle_ki angle_kd, speed_*, "
               "iq_*,\n"
               "                                 max_torque max_speed_dps max_angle_deg "
               "current_ramp\n"
               "                                 speed_ramp_dps2 (every parameter; "
               "max_angle_deg\n"
               "                                 joins 0x9B and 0x9C)\n"
               "Every WHAT reads the model first, to know the series (MS replies carry power)\n"
               "and the generation: on a V2.35 drive pid is read with read_param (plus *_kd)\n"
               "and accel does not exist; on a V2.3 drive params does not exist (exit 1,\n"
               "nothing more is sent).\n"
               "\n"
               "Options:\n"
               "  --json   one line: {\"command\":\"read_state2\",\"code\":\"0x9C\",\"id\":3,"
               "\"fields\":{...}}\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl read 3 pid --port /dev/ttyUSB0\n"
               "  lkctl read 3 multi-turn --port ttyUSB0 --json\n"
               "  lkctl read 17 state2 --sim 17:MS\n"
               "  lkctl read 1 params --sim 1:MS4015@2.35 --json\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(), exitStatusText());
}

bool ReadCommand::readInto(LiveBus &bus, Command command, int id, QJsonObject &fields)
{
    const bus::RequestResult r = bus.request(command, id);
    if (!r.ok() || !r.reply) {
        bus.reportFailure(r);
        return false;
    }
    fields = protocol::FieldJson::replyFields(*r.reply);
    return true;
}

bool ReadCommand::readV235Params(LiveBus &bus, int id, bool gainsOnly, QJsonObject &fields)
{
    // `pid`: the three loop parameters under the V2.3 names plus *_kd; `params`: all of
    // them (docs/V2.35.md section 6).
    for (const DriveParam &p : DriveParams::all()) {
        if ((p.isLoop() || !gainsOnly) && !DriveParams::readFields(bus, id, p, fields))
            return false;
    }
    return true;
}

bool ReadCommand::readCan236Params(LiveBus &bus, int id, bool gains, bool limits,
                                   QJsonObject &fields)
{
    // CAN V2.36 keeps its gains and input limits as control parameters (0xC0, one request
    // each), under the field names of their V2.35 counterparts.
    for (const protocol::ControlParamInfo &p : protocol::ControlParamTable::all()) {
        if ((p.layout == protocol::ControlParamLayout::Pid) ? !gains : !limits)
            continue;
        const protocol::BuildResult b = protocol::build::readControlParam(id, p.id);
        if (!b.ok()) {
            bus.error(b.error.message());
            return false;
        }
        const bus::RequestResult r = bus.request(*b.request);
        if (!r.ok() || !r.reply ||
            !std::holds_alternative<protocol::ControlParameter>(r.reply->payload)) {
            bus.reportFailure(r);
            return false;
        }
        const QJsonObject read = protocol::FieldJson::replyFields(*r.reply);
        for (auto it = read.begin(); it != read.end(); ++it) {
            if (!it.key().startsWith(QLatin1String("control_param"))) // the head: which one
                fields.insert(it.key(), it.value());
        }
    }
    return true;
}

int ReadCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const QStringList &pos = parser.positionals();
    if (pos.size() != 2)
        return usageError(console,
                          pos.size() < 2
                              ? QStringLiteral("expected ID and WHAT (one of %1)").arg(whatList())
                              : QStringLiteral("unexpected argument '%1'").arg(pos.at(2)));
    QString error;
    const std::optional<int> id = parseId(pos.at(0), &error);
    if (!id)
        return usageError(console, error);
    const std::optional<Command> command = commandFor(pos.at(1));
    if (!command)
        return usageError(
            console,
            QStringLiteral("cannot read '%1'; WHAT is one of %2").arg(pos.at(1), whatList()));

    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    if (*command == Command::ReadModel && bus.link() == protocol::Link::Can) {
        // Identification on CAN reads state 1 in its place: printing that as a model would
        // claim a read that never happened.
        bus.error(QStringLiteral("CAN has no read_model (0x12): drive %1's model cannot be "
                                 "read on this link; nothing was sent")
                      .arg(*id));
        return kExitFailure;
    }
    // The model first: its series and generation decide what may be asked and how the
    // replies read (a V2.35 drive has no read_pid; its gains are parameters).
    const std::optional<LiveBus::Identity> who = bus.identify(*id);
    if (!who)
        return kExitFailure;
    if (who->series && !motor::supports(*who->series, *command)) {
        bus.error(
            QStringLiteral("drive %1 is %2: that series has no %3")
                .arg(*id)
                .arg(protocol::seriesName(*who->series), protocol::CommandTable::name(*command)));
        return kExitFailure;
    }
    const bool v235 = who->model.generation == protocol::Generation::V2_35;
    if (*command == Command::ReadParam && !v235) {
        bus.error(DriveParams::noTableMessage(*id, QStringLiteral("read params")));
        return kExitFailure;
    }
    QJsonObject fields;
    const bool viaParams = *command == Command::ReadParam || (*command == Command::ReadPid && v235);
    const bool viaControl = viaParams && bus.link() == protocol::Link::Can; // CAN V2.36: 0xC0
    if (*command == Command::ReadModel)
        fields = protocol::FieldJson::replyFields(who->reply); // read once, above
    else if (viaControl  ? !readCan236Params(bus, *id, true, *command == Command::ReadParam, fields)
             : viaParams ? !readV235Params(bus, *id, *command == Command::ReadPid, fields)
                         : !readInto(bus, *command, *id, fields))
        return kExitFailure;
    if (parser.isSet(QStringLiteral("json"))) {
        OrderedJson o;
        const Command sent = viaControl  ? Command::ReadControlParam
                             : viaParams ? Command::ReadParam
                                         : *command; // what went on the wire
        o.text(QStringLiteral("command"), protocol::CommandTable::name(sent))
            .text(QStringLiteral("code"), protocol::CommandTable::codeText(quint8(sent)))
            .integer(QStringLiteral("id"), *id)
            .fields(QStringLiteral("fields"), fields);
        console.out(o.toJson() + '\n');
        return kExitOk;
    }
    console.outLine(
        QStringLiteral("Drive %1, %2:").arg(*id).arg(protocol::CommandTable::name(*command)));
    for (const QString &line : ReplyText::lines(fields, QStringLiteral("  ")))
        console.outLine(line);
    return kExitOk;
}

} // namespace lk::lkctl
