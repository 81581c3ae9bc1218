#include "CsvWriter.h"

#include <QtCore/QCoreApplication>

#include <cmath>
#include <limits>

namespace lk::record {

namespace {

// Large enough that a 600,000-row export is a few hundred writes, small enough to stay cheap.
constexpr qsizetype kFlushBytes = 1 << 16;

} // namespace

CsvWriter::CsvWriter(const QString &path) : m_file(path) {}

CsvWriter::~CsvWriter()
{
    if (m_open) {
        m_file.cancelWriting(); // never leave a half file behind
    }
}

QString CsvWriter::begin(const QStringList &header, const QVector<int> &decimals)
{
    Q_ASSERT(header.size() == decimals.size());
    if (!m_file.open(QIODevice::WriteOnly)) {
        return QCoreApplication::translate("lk::record::CsvWriter", "Cannot open %1: %2")
            .arg(m_file.fileName(), m_file.errorString());
    }
    m_open = true;
    m_decimals = decimals;
    m_error.clear();
    for (qsizetype i = 0; i < header.size(); ++i) {
        if (i > 0) {
            m_buffer += ',';
        }
        m_buffer += quoteField(header.at(i));
    }
    m_buffer += '\n';
    return {};
}

void CsvWriter::writeRow(const double *values, qsizetype count)
{
    Q_ASSERT(m_open && count == m_decimals.size());
    for (qsizetype i = 0; i < count; ++i) {
        if (i > 0) {
            m_buffer += ',';
        }
        m_buffer += formatNumber(values[i], m_decimals.at(i));
    }
    m_buffer += '\n';
    if (m_buffer.size() >= kFlushBytes) {
        flushBuffer();
    }
}

QString CsvWriter::finish()
{
    if (!m_open) {
        return m_error.isEmpty()
                   ? QCoreApplication::translate("lk::record::CsvWriter", "The file was not opened")
                   : m_error;
    }
    flushBuffer();
    m_open = false;
    if (!m_error.isEmpty()) {
        m_file.cancelWriting();
        return m_error;
    }
    if (!m_file.commit()) {
        return QCoreApplication::translate("lk::record::CsvWriter", "Cannot write %1: %2")
            .arg(m_file.fileName(), m_file.errorString());
    }
    return {};
}

void CsvWriter::flushBuffer()
{
    if (m_buffer.isEmpty() || !m_error.isEmpty()) {
        m_buffer.clear();
        return;
    }
    if (m_file.write(m_buffer) != m_buffer.size()) {
        fail(QCoreApplication::translate("lk::record::CsvWriter", "Cannot write %1: %2")
                 .arg(m_file.fileName(), m_file.errorString()));
    }
    m_buffer.clear();
}

void CsvWriter::fail(const QString &error)
{
    if (m_error.isEmpty()) {
        m_error = error; // the first error is the cause; later ones are consequences
    }
}

QByteArray CsvWriter::formatNumber(double value, int decimals)
{
    if (!std::isfinite(value)) {
        return {};
    }
    QByteArray text = QByteArray::number(value, 'f', decimals);
    if (text.startsWith('-')) {
        bool allZero = true;
        for (qsizetype i = 1; i < text.size() && allZero; ++i) {
            allZero = text.at(i) == '0' || text.at(i) == '.';
        }
        if (allZero) {
            text.remove(0, 1);
        }
    }
    return text;
}

QByteArray CsvWriter::quoteField(const QString &field)
{
    QByteArray bytes = field.toUtf8();
    if (!bytes.contains(',') && !bytes.contains('"') && !bytes.contains('\n') &&
        !bytes.contains('\r')) {
        return bytes;
    }
    bytes.replace("\"", "\"\"");
    return '"' + bytes + '"';
}

QString CsvWriter::writeAligned(const QString &path, const QVector<CsvSeries> &series,
                                int timeDecimals)
{
    QStringList header{QStringLiteral("time_s")};
    QVector<int> decimals{timeDecimals};
    for (const CsvSeries &s : series) {
        Q_ASSERT(s.times.size() == s.values.size());
        header << s.name;
        decimals << s.decimals;
    }
    CsvWriter writer(path);
    if (QString error = writer.begin(header, decimals); !error.isEmpty()) {
        return error;
    }
    constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();
    const qsizetype columns = series.size();
    QVector<qsizetype> cursor(columns, 0);
    QVector<double> row(columns + 1);
    for (;;) {
        // k-way merge: the next row is the earliest time any series has not written yet.
        double t = std::numeric_limits<double>::infinity();
        for (qsizetype c = 0; c < columns; ++c) {
            if (cursor[c] < series[c].times.size()) {
                t = std::min(t, series[c].times[cursor[c]]);
            }
        }
        if (std::isinf(t)) {
            break;
        }
        row[0] = t;
        for (qsizetype c = 0; c < columns; ++c) {
            const CsvSeries &s = series[c];
            const bool here = cursor[c] < s.times.size() && s.times[cursor[c]] == t;
            row[c + 1] = here ? s.values[cursor[c]++] : kMissing;
        }
        writer.writeRow(row.constData(), row.size());
    }
    return writer.finish();
}

} // namespace lk::record
