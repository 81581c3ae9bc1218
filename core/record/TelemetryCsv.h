#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <map>
#include <optional>

namespace lk::record {

/// How telemetry is laid out in a CSV file (docs/CSV.md).
enum class CsvLayout {
    Wide, ///< time_s, then id<N>_<column> for each drive and signal; one row per poll round
    Long, ///< time_s, id, then the columns; one row per drive per poll round
};

/// One poll round's values: its time and, per drive ID, one value per TelemetryColumns
/// column (NaN where the round brought none).
struct CycleValues {
    double time = 0; ///< seconds, when the round began
    std::map<int, QVector<double>> drives;
};

/// Formats telemetry as CSV text in either layout, with the names and precision of
/// TelemetryColumns: the header once, then the rows of one round at a time. Cells a round did
/// not sample are empty, never 0 and never a value of another round.
class TelemetryCsv {
public:
    /// A column of the wide layout: a drive and one of TelemetryColumns::all().
    struct Cell {
        int id = 0;
        int column = 0;
    };
    /// Wide layout with these columns after time_s, in this order.
    static TelemetryCsv wide(const QVector<Cell> &cells);
    /// Long layout with these TelemetryColumns indexes after time_s and id (sorted into the
    /// canonical order).
    static TelemetryCsv longLayout(QVector<int> columns);

    CsvLayout layout() const { return m_layout; }
    /// The header line, newline included.
    QByteArray header() const;
    /// The rows of one round, newline included: wide gives one row, long one per drive (by
    /// ascending ID); a row whose cells would all be empty is left out.
    QList<QByteArray> rows(const CycleValues &cycle) const;

    /// "wide" / "long".
    static QString layoutName(CsvLayout layout);
    static std::optional<CsvLayout> layoutFromName(const QString &name);
    /// Wide layout's header cell: "id3_speed_dps".
    static QString wideName(int id, int column);

    static constexpr int kTimeDecimals = 6; ///< microseconds

private:
    TelemetryCsv() = default;
    QByteArray cell(const QVector<double> &values, int column) const;

    CsvLayout m_layout = CsvLayout::Wide;
    QVector<Cell> m_cells;  // wide
    QVector<int> m_columns; // long
};

} // namespace lk::record
