#include "MonitorTable.h"

#include "OrderedJson.h"

#include <motor/SeriesLimits.h>
#include <record/CsvWriter.h>
#include <record/TelemetryColumns.h>

#include <cmath>

namespace lk::lkctl {

using bus::TelemetryFields;
using bus::TelemetrySample;
using protocol::Command;
using record::TelemetryColumns;
using record::TelemetryCsv;

namespace {

bool answers(std::optional<protocol::Series> series, Command command)
{
    return !series || motor::supports(*series, command);
}

/// The CSV layout of the columns each drive's series gives for the polled commands.
TelemetryCsv layoutFor(const QVector<Command> &commands,
                       const QMap<int, std::optional<protocol::Series>> &series,
                       MonitorFormat format, const QSet<int> &v235)
{
    QVector<TelemetryCsv::Cell> cells;
    TelemetryFields all;
    for (auto it = series.cbegin(); it != series.cend(); ++it) {
        TelemetryFields fields;
        for (Command c : commands) {
            if (answers(it.value(), c))
                fields |= TelemetrySample::fieldsOf(c, it.value(), v235.contains(it.key()));
        }
        for (int column : TelemetryColumns::of(fields))
            cells.append({it.key(), column});
        all |= fields;
    }
    return format == MonitorFormat::CsvWide ? TelemetryCsv::wide(cells)
                                            : TelemetryCsv::longLayout(TelemetryColumns::of(all));
}

} // namespace

MonitorTable::MonitorTable(const QVector<Command> &commands,
                           const QMap<int, std::optional<protocol::Series>> &series,
                           MonitorFormat format, const QSet<int> &v235)
    : m_format(format), m_csv(layoutFor(commands, series, format, v235))
{
    for (auto it = series.cbegin(); it != series.cend(); ++it) {
        for (Command c : commands)
            m_expected += answers(it.value(), c) ? 1 : 0;
    }
}

QByteArray MonitorTable::header() const
{
    return m_format == MonitorFormat::Json ? QByteArray() : m_csv.header();
}

QList<QByteArray> MonitorTable::add(const TelemetrySample &sample)
{
    if (sample.cycle == 0 || sample.cycle <= m_lastWritten)
        return {};
    QList<QByteArray> out;
    if (m_open && sample.cycle != m_open->cycle)
        out << take(); // a newer round began: the open one lost a reply
    if (!m_open) {
        m_open = Round{};
        m_open->cycle = sample.cycle;
        m_open->time = sample.cycleTime;
    }
    if (const auto [drive, first] = m_open->drives.try_emplace(sample.id, sample); !first)
        drive->second.merge(sample); // a later reply of the same round wins
    m_open->seen.insert({sample.id, int(sample.source)});
    if (m_open->seen.size() >= m_expected)
        out << take();
    return out;
}

QList<QByteArray> MonitorTable::flush()
{
    return m_open ? take() : QList<QByteArray>{};
}

QList<QByteArray> MonitorTable::take()
{
    const Round round = std::move(*m_open);
    m_open.reset();
    m_lastWritten = round.cycle;
    if (m_rounds++ == 0)
        m_firstTime = round.time;
    m_lastTime = round.time;
    record::CycleValues values;
    values.time = round.time;
    for (const auto &[id, sample] : round.drives)
        values.drives.emplace(id, TelemetryColumns::values(sample));
    return format(values);
}

QList<QByteArray> MonitorTable::format(const record::CycleValues &round) const
{
    return m_format == MonitorFormat::Json ? jsonRows(round) : m_csv.rows(round);
}

QList<QByteArray> MonitorTable::jsonRows(const record::CycleValues &round)
{
    // JSON lines: the long layout's rows as objects, keys only for values the round has.
    QList<QByteArray> out;
    const QVector<record::TelemetryColumn> &columns = TelemetryColumns::all();
    for (const auto &[id, values] : round.drives) {
        OrderedJson o;
        o.raw(QStringLiteral("time_s"),
              record::CsvWriter::formatNumber(round.time, TelemetryCsv::kTimeDecimals))
            .integer(QStringLiteral("id"), id);
        for (int c = 0; c < columns.size(); ++c) {
            if (!std::isnan(values.at(c)))
                o.raw(QLatin1String(columns.at(c).key),
                      record::CsvWriter::formatNumber(values.at(c), columns.at(c).decimals));
        }
        out << o.toJson() + '\n';
    }
    return out;
}

double MonitorTable::cyclesPerSecond() const
{
    return m_rounds > 1 && m_lastTime > m_firstTime ? (m_rounds - 1) / (m_lastTime - m_firstTime)
                                                    : 0;
}

double MonitorTable::elapsedS() const
{
    return m_lastTime - m_firstTime;
}

} // namespace lk::lkctl
