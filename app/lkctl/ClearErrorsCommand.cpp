#include "ClearErrorsCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"

#include <protocol/ErrorFlags.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>

namespace lk::lkctl {

using protocol::Command;

namespace {

/// {"error_state":9,"errors":["low_voltage","over_temperature"]}
QByteArray flagsJson(const protocol::State1 &s)
{
    QStringList names;
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::set(s.errorState, s.generation))
        names << QLatin1String(f.key);
    if (protocol::ErrorFlags::unnamedBits(s.errorState, s.generation))
        names << QStringLiteral("unknown_bits");
    OrderedJson o;
    o.integer(QStringLiteral("error_state"), s.errorState)
        .raw(QStringLiteral("errors"),
             QJsonDocument(QJsonArray::fromStringList(names)).toJson(QJsonDocument::Compact));
    return o.toJson();
}

const protocol::State1 *state1Of(const bus::RequestResult &r)
{
    return r.ok() && r.reply ? std::get_if<protocol::State1>(&r.reply->payload) : nullptr;
}

} // namespace

QString ClearErrorsCommand::summary() const
{
    return QStringLiteral("clear a drive's error flags (clear_errors) and tell which are left");
}

QString ClearErrorsCommand::example() const
{
    return QStringLiteral("lkctl clear-errors 3 --port /dev/ttyUSB0");
}

QString ClearErrorsCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl clear-errors ID (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "Read drive ID's error flags (read_state1), send clear_errors (0x9B) once and\n"
               "print the flags before and after, by the names of the drive's generation\n"
               "(V2.3: low_voltage, over_temperature; V2.35: low_voltage, over_voltage,\n"
               "driver_over_temperature, motor_over_temperature, over_current, short_circuit,\n"
               "stall, input_timeout). A drive keeps a flag while its cause persists (supply\n"
               "voltage, temperature): fix the cause, then clear again.\n"
               "\n"
               "Options:\n"
               "  --json   one line: {\"command\":\"clear_errors\",\"id\":3,\"before\":{\"error_"
               "state\":1,\n"
               "           \"errors\":[\"low_voltage\"]},\"after\":{\"error_state\":0,\"errors\""
               ":[]},\n"
               "           \"cleared\":true}\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl clear-errors 3 --port /dev/ttyUSB0\n"
               "  lkctl clear-errors 1 --sim 1:MS4015@2.35 --json\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral("  5  the drive still reports flags after the clear "
                                           "(their cause persists)\n")));
}

int ClearErrorsCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const std::optional<int> id = singleId(parser, console, &status);
    if (!id)
        return status;
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    // The model first: the generation decides how the flags read.
    if (!bus.identify(*id))
        return kExitFailure;
    const bus::RequestResult before = bus.request(Command::ReadState1, *id);
    const protocol::State1 *was = state1Of(before);
    if (!was) {
        bus.reportFailure(before);
        bus.error(QStringLiteral("nothing was cleared"));
        return kExitFailure;
    }
    const protocol::State1 flagsBefore = *was;
    const bus::RequestResult cleared = bus.request(Command::ClearErrors, *id);
    const protocol::State1 *left = state1Of(cleared);
    if (!left) {
        bus.reportFailure(cleared);
        bus.error(QStringLiteral("whether drive %1 cleared its flags is not known: read them "
                                 "with 'lkctl read %1 state1'")
                      .arg(*id));
        return kExitFailure;
    }
    const bool clean = left->errorState == 0;
    if (parser.isSet(QStringLiteral("json"))) {
        OrderedJson o;
        o.text(QStringLiteral("command"), protocol::CommandTable::name(Command::ClearErrors))
            .integer(QStringLiteral("id"), *id)
            .raw(QStringLiteral("before"), flagsJson(flagsBefore))
            .raw(QStringLiteral("after"), flagsJson(*left))
            .boolean(QStringLiteral("cleared"), clean);
        console.out(o.toJson() + '\n');
    } else {
        console.outLine(QStringLiteral("Drive %1, clear_errors:").arg(*id));
        console.outLine(
            QStringLiteral("  before  %1")
                .arg(ReplyText::errorText(flagsBefore.errorState, flagsBefore.generation)));
        console.outLine(QStringLiteral("  after   %1")
                            .arg(ReplyText::errorText(left->errorState, left->generation)));
    }
    if (clean)
        return kExitOk;
    bus.error(QStringLiteral("drive %1 still reports %2: the cause is still there (supply "
                             "voltage, temperature, a stalled or shorted motor); fix it, then "
                             "clear again")
                  .arg(*id)
                  .arg(ReplyText::errorText(left->errorState, left->generation)));
    return kExitMismatch;
}

} // namespace lk::lkctl
