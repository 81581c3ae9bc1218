#pragma once

#include "RecordingFormat.h"

#include <protocol/StreamParser.h>

#include <QtCore/QByteArray>

#include <optional>

namespace lk::recording {

/// Turns a header and records into the bytes of docs/RECORDING.md. Records collect in one
/// block; takeBlock() closes it (sync, length, base time, CRC-32) for the file. Used by the
/// writer thread and by the black box's save; it does no I/O itself.
///
/// Chunks of one direction that come within kMergeGapNs of each other, the first starting a
/// frame and all but the last ending inside it (a reply an adapter cut in two), no longer
/// together than a frame can be, become one data record with the last chunk's time: when its frames
/// were complete, which is the time a frame is stamped with live and on replay. So no frame's time
/// changes, and the file stays version 1 (the layout is the same; a chunk boundary inside a frame
/// is all that is not kept).
class RecordEncoder {
public:
    /// The longest gap between two chunks of one frame that are merged: an FTDI adapter's
    /// latency timer (16 ms) and some.
    static constexpr qint64 kMergeGapNs = 20'000'000;

    static QByteArray encodeHeader(const RecordingHeader &header);

    void append(const RecordEvent &event);
    bool isEmpty() const { return m_payload.isEmpty() && !m_data; }
    qsizetype pendingBytes() const;
    /// The block of the records appended since the last call; empty if there were none.
    QByteArray takeBlock();

    static void putContext(QByteArray &out, const ContextSnapshot &context);

private:
    /// A data record not yet written: a chunk the next one may continue.
    struct PendingData {
        RecordEvent::Kind kind = RecordEvent::Kind::Rx;
        qint64 timeNs = 0;
        QByteArray bytes;
        bool insideFrame = false; ///< its bytes completed no frame and reported no fault
    };
    void appendData(const RecordEvent &event);
    void writePendingData();
    void appendMeta(quint8 type, qint64 delta, const QByteArray &payload);
    qint64 deltaFor(qint64 timeNs);

    QByteArray m_payload;
    qint64 m_baseNs = 0;
    qint64 m_lastNs = 0;
    std::optional<PendingData> m_data;
    // Where each direction's frames end, as a reader's parser will see them.
    protocol::StreamParser m_rxFrames;
    protocol::StreamParser m_txFrames;
};

} // namespace lk::recording
