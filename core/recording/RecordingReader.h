#pragma once

#include "RecordingFormat.h"

#include <QtCore/QByteArray>
#include <QtCore/QIODevice>
#include <QtCore/QVector>

#include <memory>

namespace lk::recording {

/// Reads a recording (docs/RECORDING.md) record by record, one block in memory at a time, so
/// an hour-long file opens in bounded memory. Every block's CRC is checked before any of its
/// records is given out: a truncated or damaged file reads up to the last good block, then
/// error() names the byte offset of the damage.
class RecordingReader {
public:
    /// A block's place in the file and the time of its first record: an index for seeking.
    struct Block {
        qint64 offset = 0;
        qint64 baseTimeNs = 0;
    };

    /// True if `bytes` start with the recording magic (enough to tell a recording apart).
    static bool hasMagic(const QByteArray &bytes);

    /// Open and read the header; false with error() set if that fails.
    bool open(const QString &path);
    /// The same on bytes already in memory (standard input).
    bool openBytes(const QByteArray &bytes);

    const RecordingHeader &header() const { return m_header; }
    /// The next record; false at the end of the file or at damage (error() tells which).
    bool next(RecordEvent *event);
    /// Kind::None after a clean end; Truncated or Damaged (with its offset) otherwise.
    const RecordingError &error() const { return m_error; }

    /// Read every block from the first (CRCs checked) and go back to the first: the index for
    /// seek(), and lastTimeNs(). Stops at damage, which error() then reports.
    QVector<Block> index();
    /// The damage index() stopped at (Kind::None if it read to a clean end).
    const RecordingError &indexDamage() const { return m_indexDamage; }
    /// The time of the last record of the last good block (after index()).
    qint64 lastTimeNs() const { return m_lastTimeNs; }
    /// Continue reading at a block that index() returned.
    bool seek(const Block &block);
    qint64 size() const;

private:
    bool openDevice(std::unique_ptr<QIODevice> device, const QString &name);
    bool readHeader();
    bool readBlock();
    enum class Decoded { Record, Skipped, Failed };
    Decoded decodeRecord(RecordEvent *event);
    bool fail(RecordingError::Kind kind, qint64 offset, const QString &message);

    std::unique_ptr<QIODevice> m_device;
    QString m_name;
    RecordingHeader m_header;
    RecordingError m_error;
    RecordingError m_indexDamage;
    QByteArray m_block;
    qsizetype m_pos = 0;
    qint64 m_blockOffset = 0;
    qint64 m_firstBlockOffset = 0;
    qint64 m_timeNs = 0;
    qint64 m_lastTimeNs = 0;
};

} // namespace lk::recording
