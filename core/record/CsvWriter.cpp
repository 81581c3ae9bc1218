#include "CsvWriter.h"

#include <QtCore/QCoreApplication>

#include <cmath>

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

QString CsvWriter::begin(const QByteArray &header)
{
    if (!m_file.open(QIODevice::WriteOnly)) {
        return QCoreApplication::translate("lk::record::CsvWriter", "Cannot open %1: %2")
            .arg(m_file.fileName(), m_file.errorString());
    }
    m_open = true;
    m_error.clear();
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
        return m_error.isEmpty()
                   ? QCoreApplication::translate("lk::record::CsvWriter", "The file was not opened")
                   : m_error;
    }
    flushBuffer();
    m_open = false;
    // Qt 6.4's QSaveFile renames the file into place even when the flush inside commit()
    // fails (a full disk): flush first, where a failure still cancels.
    if (m_error.isEmpty() && !m_file.flush())
        m_error = QCoreApplication::translate("lk::record::CsvWriter", "Cannot write %1: %2")
                      .arg(m_file.fileName(), m_file.errorString());
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

} // namespace lk::record
