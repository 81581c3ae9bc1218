#pragma once

#include <system/AtomicFile.h>

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace lk::record {

/// Writes a CSV file atomically (system::AtomicFile): either the complete file appears at the
/// path or the path is left as it was (an error, or a writer destroyed before finish(),
/// discards it). The text comes formatted (TelemetryCsv); formatNumber() is the one number
/// format of every telemetry CSV: C locale, fixed decimals, NaN and infinities as empty cells
/// (no value).
class CsvWriter {
public:
    explicit CsvWriter(const QString &path);
    CsvWriter(const CsvWriter &) = delete;
    CsvWriter &operator=(const CsvWriter &) = delete;

    /// Opens the file and writes `header` (a line, newline included). Returns an error
    /// text, empty on success.
    QString begin(const QByteArray &header);
    /// Appends text (whole lines).
    void write(const QByteArray &text);
    /// Commits the file. Returns an error text, empty on success; after an error nothing
    /// was written to the path.
    QString finish();

    /// `value` with `decimals` digits, "-0.00" normalised to "0.00", empty if not finite.
    static QByteArray formatNumber(double value, int decimals);

private:
    void flushBuffer();

    system::AtomicFile m_file;
    QByteArray m_buffer;
    bool m_open = false;
};

} // namespace lk::record
