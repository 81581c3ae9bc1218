#pragma once

#include "RecordingFormat.h"

#include <QtCore/QByteArray>

namespace lk::recording {

/// Turns a header and records into the bytes of docs/RECORDING.md. Records collect in one
/// block; takeBlock() closes it (sync, length, base time, CRC-32) for the file. Used by the
/// writer thread and by the black box's save; it does no I/O itself.
class RecordEncoder {
public:
    static QByteArray encodeHeader(const RecordingHeader &header);

    void append(const RecordEvent &event);
    bool isEmpty() const { return m_payload.isEmpty(); }
    qsizetype pendingBytes() const { return m_payload.size(); }
    /// The block of the records appended since the last call; empty if there were none.
    QByteArray takeBlock();

    static void putContext(QByteArray &out, const ContextSnapshot &context);

private:
    void appendMeta(quint8 type, qint64 delta, const QByteArray &payload);
    qint64 deltaFor(qint64 timeNs);

    QByteArray m_payload;
    qint64 m_baseNs = 0;
    qint64 m_lastNs = 0;
};

} // namespace lk::recording
