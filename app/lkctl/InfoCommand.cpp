#include "InfoCommand.h"

#include "Console.h"
#include "DriveParams.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReadCommand.h"
#include "ReplyText.h"

#include <protocol/FieldJson.h>
#include <protocol/RequestBuilder.h>

namespace lk::lkctl {

using protocol::Command;
using protocol::FieldJson;

QString InfoCommand::summary() const
{
    return QStringLiteral("show one drive: model, temperature, voltage, errors, PID, accel");
}

QString InfoCommand::example() const
{
    return QStringLiteral("lkctl info 3 --port /dev/ttyUSB0");
}

QString InfoCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl info ID (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "Read drive ID's model (read_model), state 1 (read_state1), PID gains and\n"
               "acceleration and show them. A V2.3 drive answers read_pid and read_accel; a\n"
               "V2.35 drive (firmware 2.35 and later) has neither: its gains come from\n"
               "read_param (angle_pid, speed_pid, iq_pid) under the same names plus *_kd, and\n"
               "its own limits and ramps (max_torque, max_speed, max_angle, current_ramp,\n"
               "speed_ramp) are shown beside them.\n"
               "\n"
               "Options:\n"
               "  --json   one JSON object: {\"id\":3,\"series\":\"MF\",\"generation\":\"v2.3\",\n"
               "           \"model\":{...},\"state1\":{...},\"pid\":{...},\"accel\":{...}} (V2.3)\n"
               "           or ...\"pid\":{...},\"params\":{...}} (V2.35), each part with the\n"
               "           CLI.md fields of its reply\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl info 3 --port /dev/ttyUSB0\n"
               "  lkctl info 17 --port ttyUSB0 --baud 1000000 --json\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(), exitStatusText());
}

void InfoCommand::print(Console &console, int id, const LiveBus::Identity &who,
                        const QList<QPair<QString, QJsonObject>> &parts, bool json) const
{
    protocol::Reply model;
    model.command = Command::ReadModel;
    model.id = quint8(id);
    model.payload = who.model;
    const QJsonObject modelFields = FieldJson::replyFields(model);
    const QString series = who.series ? protocol::seriesName(*who.series) : QString();
    if (json) {
        OrderedJson o;
        o.integer(QStringLiteral("id"), id);
        if (who.series)
            o.text(QStringLiteral("series"), series);
        else
            o.null(QStringLiteral("series"));
        o.text(QStringLiteral("generation"), protocol::generationName(who.model.generation));
        if (who.modelRead)
            o.fields(QStringLiteral("model"), modelFields);
        else
            o.null(QStringLiteral("model")); // CAN: nothing of the model was read
        for (const auto &[key, fields] : parts)
            o.fields(key, fields);
        console.out(o.toJson() + '\n');
        return;
    }
    protocol::DecodeContext dialect;
    dialect.generation = who.model.generation;
    dialect.link = who.modelRead ? protocol::Link::Rs485 : protocol::Link::Can;
    console.outLine(
        QStringLiteral("Drive %1: %2 series, %3%4")
            .arg(id)
            .arg(series.isEmpty() ? QStringLiteral("unknown") : series)
            .arg(protocol::dialectName(dialect))
            .arg(who.modelRead ? QString() : QStringLiteral(" (CAN has no model read)")));
    // The model first (it names the drive), then what it reports, one aligned block.
    QJsonObject reported;
    for (const auto &[key, fields] : parts) {
        for (auto it = fields.begin(); it != fields.end(); ++it)
            reported.insert(it.key(), it.value());
    }
    const QList<QJsonObject> blocks =
        who.modelRead ? QList<QJsonObject>{modelFields, reported} : QList<QJsonObject>{reported};
    for (const QString &line : ReplyText::lines(blocks, QStringLiteral("  ")))
        console.outLine(line);
}

int InfoCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    if (parser.positionals().size() != 1)
        return usageError(console, parser.positionals().isEmpty()
                                       ? QStringLiteral("missing the drive ID")
                                       : QStringLiteral("expected one ID, got '%1'")
                                             .arg(parser.positionals().join(QLatin1Char(' '))));
    QString error;
    const std::optional<int> id = parseId(parser.positionals().first(), &error);
    if (!id)
        return usageError(console, error);

    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const std::optional<LiveBus::Identity> who = bus.identify(*id);
    if (!who)
        return kExitFailure;
    QList<QPair<QString, QJsonObject>> parts;
    const bool failed = who->model.generation == protocol::Generation::V2_3
                            ? !readV23(bus, *id, parts)
                            : !readV235(bus, *id, parts);
    print(console, *id, *who, parts, parser.isSet(QStringLiteral("json")));
    return failed ? kExitFailure : kExitOk;
}

bool InfoCommand::readInto(LiveBus &bus, const protocol::Request &request, QJsonObject &into)
{
    const bus::RequestResult r = bus.request(request);
    if (!r.ok() || !r.reply) {
        bus.reportFailure(r);
        return false;
    }
    const QJsonObject fields = FieldJson::replyFields(*r.reply);
    for (auto it = fields.begin(); it != fields.end(); ++it)
        into.insert(it.key(), it.value());
    return true;
}

bool InfoCommand::readV23(LiveBus &bus, int id, QList<QPair<QString, QJsonObject>> &parts)
{
    bool ok = true;
    for (const auto &[key, command] : {std::pair{"state1", Command::ReadState1},
                                       {"pid", Command::ReadPid},
                                       {"accel", Command::ReadAccel}}) {
        QJsonObject fields;
        if (readInto(bus, *protocol::build::plain(command, id).request, fields))
            parts.append({QLatin1String(key), fields});
        else
            ok = false;
    }
    return ok;
}

bool InfoCommand::readV235(LiveBus &bus, int id, QList<QPair<QString, QJsonObject>> &parts)
{
    // V2.35 has no 0x30/0x33 (docs/V2.35.md section 3): the gains come from the parameter table,
    // under the V2.3 names plus *_kd, and the drive's own limits and ramps beside them.
    QJsonObject state1, pid, params;
    bool ok = readInto(bus, *protocol::build::plain(Command::ReadState1, id).request, state1);
    // CAN V2.36 has no parameter table: its gains and limits are control parameters (0xC0).
    if (bus.link() == protocol::Link::Can)
        ok &= ReadCommand::readCan236Params(bus, id, true, false, pid) &&
              ReadCommand::readCan236Params(bus, id, false, true, params);
    else
        ok &= DriveParams::readAll(bus, id, pid, params);
    if (!state1.isEmpty())
        parts.append({QStringLiteral("state1"), state1});
    if (!pid.isEmpty())
        parts.append({QStringLiteral("pid"), pid});
    if (!params.isEmpty())
        parts.append({QStringLiteral("params"), params});
    return ok;
}

} // namespace lk::lkctl
