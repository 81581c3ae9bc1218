#pragma once

#include <bus/TelemetrySample.h>
#include <protocol/Command.h>
#include <protocol/Series.h>
#include <record/TelemetryCsv.h>

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QSet>
#include <QtCore/QVector>

#include <map>
#include <optional>

namespace lk::lkctl {

/// What `lkctl monitor` prints.
enum class MonitorFormat { CsvWide, CsvLong, Json };

/// Turns the telemetry of `lkctl monitor` into rows, one poll round at a time (docs/CSV.md):
/// a row holds only values of one round, stamped with the time the round began. CSV wide:
/// one row per round, a column per drive and signal; CSV long and JSON lines: one row per
/// drive per round. A round is written when every poll of it has answered, or when the next
/// round's first reply arrives (a reply of it was lost: its cells stay empty).
class MonitorTable {
public:
    /// `commands`: what is polled; `series`: per ID (nullopt: unknown, read as MF);
    /// `v235`: the IDs that speak V2.35 (their read_state1 also carries bus current and the
    /// motor state).
    MonitorTable(const QVector<protocol::Command> &commands,
                 const QMap<int, std::optional<protocol::Series>> &series, MonitorFormat format,
                 const QSet<int> &v235 = {});

    /// The CSV header line (empty for JSON), newline included.
    QByteArray header() const;
    /// Takes one sample; returns the rows it completed, newline included. Samples that
    /// answer no poll (cycle 0) or a round already written are ignored.
    QList<QByteArray> add(const bus::TelemetrySample &sample);
    /// The rows of the round still open (partial), at the end of monitoring.
    QList<QByteArray> flush();
    /// JSON lines of `round`: the long layout's rows as objects, one per drive, with keys
    /// only for the values it has (`lkctl listen` writes the same).
    static QList<QByteArray> jsonRows(const record::CycleValues &round);
    /// Poll rounds per second (each drive is polled once a round).
    double cyclesPerSecond() const;
    /// From the first round written to the last, seconds.
    double elapsedS() const;

private:
    struct Round {
        quint64 cycle = 0;
        double time = 0;                            ///< when the round began
        std::map<int, bus::TelemetrySample> drives; ///< per ID, the round's replies merged
        QSet<QPair<int, int>> seen;                 ///< (id, command) that answered
    };
    QList<QByteArray> take();
    QList<QByteArray> format(const record::CycleValues &round) const;

    MonitorFormat m_format;
    record::TelemetryCsv m_csv;
    int m_expected = 0; ///< polls per round: the commands each drive's series answers
    std::optional<Round> m_open;
    quint64 m_lastWritten = 0;
    int m_rounds = 0;
    double m_firstTime = 0, m_lastTime = 0;
};

} // namespace lk::lkctl
