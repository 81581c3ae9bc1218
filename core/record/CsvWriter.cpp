#include "CsvWriter.h"

#include <QtCore/QCoreApplication>

#include <cmath>

namespace lk::record {

namespace {

// Large enough that a 600,000-row export is a few hundred writes, small enough to stay cheap.
constexpr qsizetype kFlushBytes = 1 << 16;

} // namespace

CsvWriter::CsvWriter(const QString &path) : m_file(path) {}

QString CsvWriter::begin(const QByteArray &header)
{
    if (!m_file.open()) {
        return QCoreApplication::translate("lk::record::CsvWriter", "Cannot open %1: %2")
            .arg(m_file.fileName(), m_file.errorString());
    }
    m_open = true;
    m_buffer = header;
    return {};
}

void CsvWriter::write(const QByteArray &text)
{
    Q_ASSERT(m_open);
    m_buffer += text;
    if (m_buffer.size() >= kFlushBytes) {
        flushBuffer();
    }
}

QString CsvWriter::finish()
{
    if (!m_open) {
        return QCoreApplication::translate("lk::record::CsvWriter", "The file was not opened");
    }
    flushBuffer();
    m_open = false;
    if (!m_file.commit()) {
        return QCoreApplication::translate("lk::record::CsvWriter", "Cannot write %1: %2")
            .arg(m_file.fileName(), m_file.errorString());
    }
    return {};
}

void CsvWriter::flushBuffer()
{
    // A failed write is kept by the file: finish() reports the first one and discards it all.
    m_file.write(m_buffer);
    m_buffer.clear();
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

} // namespace lk::record
