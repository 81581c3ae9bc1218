#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QSaveFile>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

namespace lk::record {

/// One column of a time-aligned CSV file: its header cell, its precision and its points.
struct CsvSeries {
    QString name;           ///< header cell, e.g. "id3_iq_a"
    int decimals = 6;       ///< digits after the decimal point
    QVector<double> times;  ///< seconds, ascending
    QVector<double> values; ///< one per time
};

/// Writes a CSV file through QSaveFile: either the complete file appears at the path or the
/// path is left as it was (an error, or a writer destroyed before finish(), discards it).
/// Numbers are written in the C locale with a fixed number of decimals per column; NaN and
/// infinities are written as empty cells (a missing value).
class CsvWriter {
public:
    explicit CsvWriter(const QString &path);
    ~CsvWriter();
    CsvWriter(const CsvWriter &) = delete;
    CsvWriter &operator=(const CsvWriter &) = delete;

    /// Opens the file and writes the header row; `decimals` gives each column's precision.
    /// Returns an error text, empty on success.
    QString begin(const QStringList &header, const QVector<int> &decimals);
    /// Writes one row of `count` cells (count must equal the header's size).
    void writeRow(const double *values, qsizetype count);
    /// Commits the file. Returns an error text, empty on success; after an error nothing
    /// was written to the path.
    QString finish();

    /// Writes `time_s` and one column per series. Decision on alignment: one row per
    /// distinct timestamp, in time order; a series fills the cell of a row only when it has
    /// a point at exactly that time, else the cell is empty. Signals read from the same reply
    /// share their timestamp and so share a row; drives polled at different moments get rows
    /// of their own. No value is ever interpolated or repeated.
    static QString writeAligned(const QString &path, const QVector<CsvSeries> &series,
                                int timeDecimals = 6);

    /// `value` with `decimals` digits, "-0.00" normalised to "0.00", empty if not finite.
    static QByteArray formatNumber(double value, int decimals);
    /// A header cell, quoted (RFC 4180) when it holds a comma, a quote or a line break.
    static QByteArray quoteField(const QString &field);

private:
    void flushBuffer();
    void fail(const QString &error);

    QSaveFile m_file;
    QVector<int> m_decimals;
    QByteArray m_buffer;
    QString m_error;
    bool m_open = false;
};

} // namespace lk::record
