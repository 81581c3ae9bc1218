#pragma once

#include <bus/TelemetrySample.h>
#include <protocol/Command.h>
#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

/// Turns the telemetry of `lkctl monitor` into rows: one row per drive per poll cycle, the
/// fields of every polled command merged, as CSV (with a header whose names carry the unit)
/// or as JSON lines. A row is complete when each command polled for that drive has answered,
/// or when one answers again (the previous cycle lost a reply: the row goes out without it).
class MonitorTable {
public:
    /// `commands`: what is polled; `series`: per ID (nullopt: unknown, read as MF).
    MonitorTable(const QVector<protocol::Command> &commands,
                 const QMap<int, std::optional<protocol::Series>> &series, bool json);

    /// The CSV header line (empty for JSON), newline included.
    QByteArray header() const;
    /// Merge one sample; returns the rows it completed, newline included.
    QList<QByteArray> add(const bus::TelemetrySample &sample);
    /// The rows still being merged (partial), at the end of monitoring.
    QList<QByteArray> flush();
    int rowCount() const { return m_rows; }
    /// Rows per second of one drive (poll cycles it completed), averaged over the drives.
    double cyclesPerSecond() const;
    /// From the first row to the last, seconds.
    double elapsedS() const;

    /// The fields a command's reply carries, for a series.
    static bus::TelemetryFields fieldsOf(protocol::Command command,
                                         std::optional<protocol::Series> series);

private:
    struct Pending {
        bus::TelemetrySample merged;
        QVector<protocol::Command> seen;
        bool empty = true;
    };
    struct Column {
        const char *name;
        bus::TelemetryField field;
    };
    QByteArray format(const bus::TelemetrySample &row);
    QByteArray take(Pending &p);
    bool complete(int id, const Pending &p) const;

    QVector<protocol::Command> m_commands;
    QMap<int, std::optional<protocol::Series>> m_series;
    QVector<Column> m_columns;
    struct Span {
        int rows = 0;
        double first = 0, last = 0;
    };
    QMap<int, Pending> m_pending;
    QMap<int, Span> m_spans; ///< per ID
    bool m_json;
    int m_rows = 0;
};

} // namespace lk::lkctl
