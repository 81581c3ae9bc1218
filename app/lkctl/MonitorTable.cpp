#include "MonitorTable.h"

#include "OrderedJson.h"

#include <motor/SeriesLimits.h>

#include <algorithm>

namespace lk::lkctl {

using bus::TelemetryField;
using bus::TelemetryFields;
using bus::TelemetrySample;
using protocol::Command;

namespace {

/// The value of one column of a merged row, as JSON/CSV text.
QByteArray valueText(const char *column, const TelemetrySample &s)
{
    const QByteArray c(column);
    if (c == "temperature_c")
        return QByteArray::number(s.temperatureC);
    if (c == "voltage_v")
        return QByteArray::number(s.voltageV, 'f', 1);
    if (c == "error_state")
        return QByteArray::number(s.errorState);
    if (c == "iq_a")
        return OrderedJson::realText(s.iqA);
    if (c == "power")
        return QByteArray::number(s.power);
    if (c == "speed_dps")
        return OrderedJson::realText(s.speedDps);
    if (c == "encoder")
        return QByteArray::number(s.encoder);
    // Angles come in 0.01 deg: two places, without the binary noise of raw * 0.01.
    if (c == "multi_turn_deg")
        return QByteArray::number(s.multiTurnDeg, 'f', 2);
    if (c == "single_turn_deg")
        return QByteArray::number(s.singleTurnDeg, 'f', 2);
    if (c == "ia_a")
        return OrderedJson::realText(s.iaA);
    if (c == "ib_a")
        return OrderedJson::realText(s.ibA);
    return OrderedJson::realText(s.icA);
}

void merge(TelemetrySample &into, const TelemetrySample &s)
{
    if (s.has(TelemetryField::Temperature))
        into.temperatureC = s.temperatureC;
    if (s.has(TelemetryField::IqA))
        into.iqA = s.iqA;
    if (s.has(TelemetryField::Power))
        into.power = s.power;
    if (s.has(TelemetryField::Speed))
        into.speedDps = s.speedDps;
    if (s.has(TelemetryField::Encoder))
        into.encoder = s.encoder;
    if (s.has(TelemetryField::Voltage))
        into.voltageV = s.voltageV;
    if (s.has(TelemetryField::ErrorState))
        into.errorState = s.errorState;
    if (s.has(TelemetryField::MultiTurn))
        into.multiTurnDeg = s.multiTurnDeg;
    if (s.has(TelemetryField::SingleTurn))
        into.singleTurnDeg = s.singleTurnDeg;
    if (s.has(TelemetryField::PhaseCurrents)) {
        into.iaA = s.iaA;
        into.ibA = s.ibA;
        into.icA = s.icA;
    }
    into.fields |= s.fields;
}

} // namespace

TelemetryFields MonitorTable::fieldsOf(Command command, std::optional<protocol::Series> series)
{
    switch (command) {
    case Command::ReadState1:
        return TelemetryField::Temperature | TelemetryField::Voltage | TelemetryField::ErrorState;
    case Command::ReadState2:
        return TelemetryField::Temperature | TelemetryField::Speed | TelemetryField::Encoder |
               (series == protocol::Series::MS ? TelemetryField::Power : TelemetryField::IqA);
    case Command::ReadState3:
        return TelemetryField::Temperature | TelemetryField::PhaseCurrents;
    case Command::ReadMultiTurn:
        return TelemetryField::MultiTurn;
    case Command::ReadSingleTurn:
        return TelemetryField::SingleTurn;
    case Command::ReadEncoder:
        return TelemetryField::Encoder;
    default:
        return {};
    }
}

MonitorTable::MonitorTable(const QVector<Command> &commands,
                           const QMap<int, std::optional<protocol::Series>> &series, bool json)
    : m_commands(commands), m_series(series), m_json(json)
{
    TelemetryFields all;
    for (auto it = series.cbegin(); it != series.cend(); ++it) {
        for (Command c : commands) {
            if (!it.value() || motor::supports(*it.value(), c))
                all |= fieldsOf(c, it.value());
        }
    }
    static const Column kColumns[] = {
        {"temperature_c", TelemetryField::Temperature},
        {"voltage_v", TelemetryField::Voltage},
        {"error_state", TelemetryField::ErrorState},
        {"iq_a", TelemetryField::IqA},
        {"power", TelemetryField::Power},
        {"speed_dps", TelemetryField::Speed},
        {"encoder", TelemetryField::Encoder},
        {"multi_turn_deg", TelemetryField::MultiTurn},
        {"single_turn_deg", TelemetryField::SingleTurn},
        {"ia_a", TelemetryField::PhaseCurrents},
        {"ib_a", TelemetryField::PhaseCurrents},
        {"ic_a", TelemetryField::PhaseCurrents},
    };
    for (const Column &c : kColumns) {
        if (all.testFlag(c.field))
            m_columns.append(c);
    }
}

QByteArray MonitorTable::header() const
{
    if (m_json)
        return {};
    QByteArray h = "time_s,id";
    for (const Column &c : m_columns)
        h += QByteArray(",") + c.name;
    return h + '\n';
}

bool MonitorTable::complete(int id, const Pending &p) const
{
    const std::optional<protocol::Series> series = m_series.value(id);
    for (Command c : m_commands) {
        if ((!series || motor::supports(*series, c)) && !p.seen.contains(c))
            return false;
    }
    return true;
}

QList<QByteArray> MonitorTable::add(const TelemetrySample &sample)
{
    QList<QByteArray> out;
    Pending &p = m_pending[sample.id];
    if (p.seen.contains(sample.source))
        out << take(p); // a new cycle began: the last one lost a reply
    if (p.empty) {
        p.merged = TelemetrySample{};
        p.merged.id = sample.id;
        p.merged.time = sample.time;
        p.empty = false;
    }
    merge(p.merged, sample);
    p.seen.append(sample.source);
    if (complete(sample.id, p))
        out << take(p);
    return out;
}

QList<QByteArray> MonitorTable::flush()
{
    QList<QByteArray> out;
    for (Pending &p : m_pending) {
        if (!p.empty)
            out << take(p);
    }
    return out;
}

double MonitorTable::cyclesPerSecond() const
{
    double sum = 0;
    int drives = 0;
    for (const Span &s : m_spans) {
        if (s.rows > 1 && s.last > s.first) {
            sum += (s.rows - 1) / (s.last - s.first);
            ++drives;
        }
    }
    return drives > 0 ? sum / drives : 0;
}

double MonitorTable::elapsedS() const
{
    double first = 0, last = 0;
    bool any = false;
    for (const Span &s : m_spans) {
        first = any ? std::min(first, s.first) : s.first;
        last = any ? std::max(last, s.last) : s.last;
        any = true;
    }
    return last - first;
}

QByteArray MonitorTable::take(Pending &p)
{
    const QByteArray row = format(p.merged);
    ++m_rows;
    Span &span = m_spans[p.merged.id];
    if (span.rows++ == 0)
        span.first = p.merged.time;
    span.last = p.merged.time;
    p.seen.clear();
    p.empty = true;
    return row;
}

QByteArray MonitorTable::format(const TelemetrySample &row)
{
    const QByteArray time = QByteArray::number(row.time, 'f', 6);
    if (m_json) {
        OrderedJson o;
        o.raw(QStringLiteral("time_s"), time).integer(QStringLiteral("id"), row.id);
        for (const Column &c : m_columns) {
            if (row.has(c.field))
                o.raw(QLatin1String(c.name), valueText(c.name, row));
        }
        return o.toJson() + '\n';
    }
    QByteArray line = time + ',' + QByteArray::number(row.id);
    for (const Column &c : m_columns) {
        line += ',';
        if (row.has(c.field))
            line += valueText(c.name, row);
    }
    return line + '\n';
}

} // namespace lk::lkctl
