#include "ScanCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"

#include <protocol/ErrorFlags.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <protocol/Series.h>

namespace lk::lkctl {

namespace {

/// read_state1's values as the generation reads them: bus current and motor state exist only
/// on V2.35 (null otherwise); `errors` names the set flags the generation defines.
void addState(OrderedJson &o, const bus::FoundMotor &m)
{
    if (!m.state1 || !m.modelKnown) {
        // Without the model the generation, and so the layout, is unknown: show nothing
        // rather than a voltage read with the wrong layout.
        for (const char *key :
             {"temperature_c", "voltage_v", "bus_current_a", "motor_on", "error_state", "errors"})
            o.null(QLatin1String(key));
        return;
    }
    const protocol::State1 &s = *m.state1;
    o.integer(QStringLiteral("temperature_c"), s.temperatureC)
        .real(QStringLiteral("voltage_v"), s.voltageV());
    if (const std::optional<double> a = s.busCurrentA())
        o.real(QStringLiteral("bus_current_a"), *a);
    else
        o.null(QStringLiteral("bus_current_a"));
    if (const std::optional<bool> on = s.motorOn())
        o.boolean(QStringLiteral("motor_on"), *on);
    else
        o.null(QStringLiteral("motor_on"));
    o.integer(QStringLiteral("error_state"), s.errorState);
    QStringList errors;
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::set(s.errorState, s.generation))
        errors << QLatin1String(f.key);
    if (protocol::ErrorFlags::unnamedBits(s.errorState, s.generation))
        errors << QStringLiteral("unknown_bits");
    o.raw(QStringLiteral("errors"),
          QJsonDocument(QJsonArray::fromStringList(errors)).toJson(QJsonDocument::Compact));
}

/// CLI.md's shape; a drive whose read_model went unanswered has nulls, not empty names and
/// version 0. With a baud sweep each entry says at which baud it answered.
QByteArray jsonArray(const QVector<bus::FoundMotor> &motors, bool withBaud)
{
    QByteArray out = "[";
    for (qsizetype i = 0; i < motors.size(); ++i) {
        const bus::FoundMotor &m = motors.at(i);
        OrderedJson o;
        o.integer(QStringLiteral("id"), m.id);
        if (m.modelKnown) {
            o.text(QStringLiteral("driver_name"), m.model.driverName)
                .text(QStringLiteral("motor_name"), m.model.motorName)
                .real(QStringLiteral("hardware_version"), m.model.hardwareVersion())
                .real(QStringLiteral("firmware_version"), m.model.firmwareVersion());
        } else {
            for (const char *key :
                 {"driver_name", "motor_name", "hardware_version", "firmware_version"})
                o.null(QLatin1String(key));
        }
        if (m.series)
            o.text(QStringLiteral("series"), protocol::seriesName(*m.series));
        else
            o.null(QStringLiteral("series"));
        // On CAN no model is read: the generation is what the reply told or the user said
        // (v2.3: the old CAN generation, v2.35: CAN V2.36; "dialect" names it).
        const std::optional<protocol::Generation> generation =
            m.modelKnown ? std::optional<protocol::Generation>(m.model.generation) : m.generation;
        if (generation)
            o.text(QStringLiteral("generation"), protocol::generationName(*generation));
        else
            o.null(QStringLiteral("generation"));
        if (m.link == protocol::Link::Can)
            o.text(QStringLiteral("dialect"),
                   generation ? protocol::dialectName({m.series.value_or(protocol::Series::MF),
                                                       *generation, protocol::Link::Can})
                              : QStringLiteral("CAN"));
        addState(o, m);
        if (withBaud)
            o.integer(QStringLiteral("baud"), m.baud);
        out += (i > 0 ? "," : "") + o.toJson();
    }
    return out + "]";
}

QString versionText(double version, double divisor)
{
    return QString::number(version, 'f', divisor > 10 ? 2 : 1);
}

QStringList tableRow(const bus::FoundMotor &m, bool withBaud)
{
    QStringList row{QString::number(m.id),
                    m.series ? protocol::seriesName(*m.series) : QStringLiteral("?"),
                    m.model.driverName.isEmpty() ? QStringLiteral("-") : m.model.driverName,
                    m.model.motorName.isEmpty() ? QStringLiteral("-") : m.model.motorName,
                    m.modelKnown ? versionText(m.model.hardwareVersion(), m.model.divisor())
                                 : QStringLiteral("-"),
                    m.modelKnown ? versionText(m.model.firmwareVersion(), m.model.divisor())
                                 : QStringLiteral("-")};
    if (m.state1 && m.modelKnown) {
        const protocol::State1 &s = *m.state1;
        const bool v23 = s.generation == protocol::Generation::V2_3;
        row << (v23 ? QStringLiteral("V2.3") : QStringLiteral("V2.35"))
            << QStringLiteral("%1 C").arg(s.temperatureC)
            << QStringLiteral("%1 V").arg(s.voltageV(), 0, 'f', v23 ? 1 : 2)
            << (s.busCurrentA() ? QStringLiteral("%1 A").arg(*s.busCurrentA(), 0, 'f', 2)
                                : QStringLiteral("-"))
            << ReplyText::errorText(s.errorState, s.generation);
    } else {
        row << QStringLiteral("-") << QStringLiteral("-") << QStringLiteral("-")
            << QStringLiteral("-") << QStringLiteral("-");
    }
    if (withBaud)
        row << QString::number(m.baud);
    return row;
}

void printTable(Console &console, const QVector<bus::FoundMotor> &motors, bool withBaud)
{
    QList<QStringList> rows{{"ID", "Series", "Driver", "Motor", "HW", "FW", "Protocol", "Temp",
                             "Voltage", "Current", "Errors"}};
    if (withBaud)
        rows.first() << QStringLiteral("Baud");
    for (const bus::FoundMotor &m : motors)
        rows << tableRow(m, withBaud);
    QVector<qsizetype> width(rows.first().size(), 0);
    for (const QStringList &r : rows) {
        for (qsizetype i = 0; i < r.size(); ++i)
            width[i] = std::max(width[i], r.at(i).size());
    }
    for (const QStringList &r : rows) {
        QString line;
        for (qsizetype i = 0; i < r.size(); ++i)
            line += (i == 0 ? r.at(i).rightJustified(width[i]) : r.at(i).leftJustified(width[i])) +
                    QStringLiteral("  ");
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        console.outLine(line);
    }
}

} // namespace

QString ScanCommand::summary() const
{
    return QStringLiteral("find the drives on a bus: ID, series, model, state");
}

QString ScanCommand::example() const
{
    return QStringLiteral("lkctl scan --port /dev/ttyUSB0 --baud 115200");
}

QString ScanCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl scan (--port DEV [--baud N] | --sim SPEC) [--from ID] [--to ID]\n"
               "                  [--sweep-bauds] [--retries N] [--json]\n"
               "\n"
               "Probe every ID of a range (1..32 by default) with read_state1, then read the\n"
               "model of each drive that answers. The first pass waits only as long as a\n"
               "drive on a fast link needs (a full scan at 115200 baud takes ~0.2 s); when a\n"
               "reply comes late (a USB adapter's latency), silent IDs are probed again with\n"
               "the timeout the bus has learned, so a slow link is slower but complete.\n"
               "\n"
               "Options:\n"
               "  --from ID, --to ID  the ID range (default 1 and 32)\n"
               "  --sweep-bauds       scan at each of the ten bauds (slow); the bus ends at\n"
               "                      the baud where most drives answered\n"
               "  --retries N         probe silent IDs again N more times with the full\n"
               "                      timeout (default 0: only when a late reply was seen)\n"
               "  --json              print exactly one JSON array:\n"
               "    [{\"id\":3,\"driver_name\":\"...\",\"motor_name\":\"MF4015\","
               "\"hardware_version\":1.0,\n"
               "      \"firmware_version\":2.3,\"series\":\"MF\",\"generation\":\"v2.3\",\n"
               "      \"temperature_c\":31,\"voltage_v\":24.1,\"bus_current_a\":null,"
               "\"motor_on\":null,\n"
               "      \"error_state\":0,\"errors\":[]}]\n"
               "    series null when the model names none; names, versions, generation and\n"
               "    the state null when the drive answered but read_model did not (without\n"
               "    the generation its state cannot be read); bus_current_a and motor_on\n"
               "    exist on V2.35 drives only (null on V2.3); errors lists the set flags by\n"
               "    name: low_voltage, over_temperature (V2.3); low_voltage, over_voltage,\n"
               "    driver_over_temperature, motor_over_temperature, over_current,\n"
               "    short_circuit, stall, input_timeout (V2.35); unknown_bits for the rest;\n"
               "    with --sweep-bauds each entry also has \"baud\"\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl scan --port /dev/ttyUSB0\n"
               "  lkctl scan --port ttyUSB0 --baud 1000000 --from 1 --to 8 --json\n"
               "  lkctl scan --port /dev/ttyUSB0 --sweep-bauds\n"
               "  lkctl scan --sim 3:MF,17:MS,32:MG\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral("  An empty bus is not an error: the table says so "
                                           "and --json prints [].\n")));
}

bool ScanCommand::readRange(const ArgParser &parser, bus::ScanOptions &o, Console &console,
                            int *status) const
{
    QString error;
    for (const auto &[option, target] : {std::pair{"from", &o.firstId}, {"to", &o.lastId}}) {
        if (!parser.isSet(QLatin1String(option)))
            continue;
        const std::optional<int> id = parseId(parser.value(QLatin1String(option)), &error,
                                              QStringLiteral("--%1").arg(QLatin1String(option)));
        if (!id) {
            *status = usageError(console, error);
            return false;
        }
        *target = *id;
    }
    if (o.firstId > o.lastId) {
        *status = usageError(
            console, QStringLiteral("--from %1 is above --to %2").arg(o.firstId).arg(o.lastId));
        return false;
    }
    if (parser.isSet(QStringLiteral("retries"))) {
        const auto r = parser.intValue(QStringLiteral("retries"), 0, 5, &error);
        if (!r) {
            *status = usageError(console, error);
            return false;
        }
        o.retries = int(*r);
    }
    return true;
}

int ScanCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    parser.addOption(QStringLiteral("from"), true);
    parser.addOption(QStringLiteral("to"), true);
    parser.addOption(QStringLiteral("sweep-bauds"), false);
    parser.addOption(QStringLiteral("retries"), true);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    if (!parser.positionals().isEmpty())
        return usageError(console,
                          QStringLiteral("unexpected argument '%1'").arg(parser.positionals()[0]));
    bus::ScanOptions o;
    if (!readRange(parser, o, console, &status))
        return status;
    o.sweepBauds = parser.isSet(QStringLiteral("sweep-bauds"));

    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const bus::ScanSummary s = bus.scan(o);
    if (!s.error.isEmpty()) {
        bus.error(QStringLiteral("scan stopped: %1").arg(s.error));
        return kExitFailure;
    }
    if (parser.isSet(QStringLiteral("json"))) {
        console.out(jsonArray(s.motors, o.sweepBauds) + '\n');
    } else if (s.motors.isEmpty()) {
        console.outLine(
            QStringLiteral("No drive answered on IDs %1..%2 at %3 baud (%4 ms).")
                .arg(o.firstId)
                .arg(o.lastId)
                .arg(o.sweepBauds ? QStringLiteral("any") : QString::number(s.finalBaud))
                .arg(qRound(s.elapsedS * 1e3)));
    } else {
        printTable(console, s.motors, o.sweepBauds);
        console.outLine(
            QStringLiteral("%1 drive(s) on IDs %2..%3, bus at %4 baud, scanned in %5 ms")
                .arg(s.motors.size())
                .arg(o.firstId)
                .arg(o.lastId)
                .arg(s.finalBaud)
                .arg(qRound(s.elapsedS * 1e3)));
    }
    return kExitOk;
}

} // namespace lk::lkctl
