#pragma once

#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::recording {

// The byte layout is docs/RECORDING.md; these constants are its names.
inline constexpr char kMagic[8] = {'\x89', 'L', 'K', 'R', 'E', 'C', '\r', '\n'};
inline constexpr quint16 kFormatVersion = 1;
inline constexpr char kBlockSync[4] = {'\xB1', '\x0C', 'L', 'K'};
inline constexpr qsizetype kBlockHeaderSize = 4 + 4 + 8 + 4; ///< sync, length, base time, CRC
inline constexpr qsizetype kMaxBlockPayload = 16 * 1024 * 1024;

/// What kind of link a recording was made on.
enum class LinkKind : quint8 { Serial = 0, Simulated = 1, Can = 2, Replay = 3, Other = 255 };

/// A connection event of the recorded link.
enum class LinkEventKind : quint8 {
    Opened = 1,       ///< the link opened (at `baud`)
    Closed = 2,       ///< closed by the tool
    BaudChanged = 3,  ///< reopened at another baud (a sweep, a baud change)
    Error = 4,        ///< the transport reported an error (`text`)
    Disconnected = 5, ///< the link was lost while open
};

/// How one drive decoded at a moment: series (unknown decodes as MF) and generation.
struct DriveContext {
    int id = 0;
    std::optional<protocol::Series> series;
    protocol::Generation generation = protocol::Generation::V2_3;
    /// The user chose series and generation (bus::KnownMotor::identityChosen): a reply's hint
    /// never overrides them on replay, as it does not live (docs/RECORDING.md "Context").
    bool chosen = false;
    bool operator==(const DriveContext &o) const
    {
        return id == o.id && series == o.series && generation == o.generation && chosen == o.chosen;
    }
};
using ContextSnapshot = QVector<DriveContext>;

/// The file header: what was recorded, on which link, when.
struct RecordingHeader {
    quint16 version = kFormatVersion;
    QString toolVersion;
    LinkKind linkKind = LinkKind::Serial;
    QString linkDescription; ///< "/dev/ttyUSB0 @ 115200"
    int baud = 0;
    qint64 wallClockStartMs = 0; ///< UTC, ms since the epoch, at session time 0
    ContextSnapshot context;     ///< the decode context at the first record
};

/// What the Rx and Tx bytes of a recording made on `header`'s link are: CAN records
/// (protocol/CanRecord.h) on a CAN link, else the RS485 byte stream.
inline protocol::Link linkOf(const RecordingHeader &header)
{
    return header.linkKind == LinkKind::Can ? protocol::Link::Can : protocol::Link::Rs485;
}

/// One record: bytes that passed the link, a link event, a decode-context snapshot, or bytes
/// the recorder had to drop. `timeNs` is the session clock (ns since the recording started).
struct RecordEvent {
    enum class Kind : quint8 { Rx, Tx, Link, Context, Dropped };
    Kind kind = Kind::Rx;
    qint64 timeNs = 0;
    QByteArray bytes;                           ///< Rx, Tx
    LinkEventKind link = LinkEventKind::Opened; ///< Link
    int baud = 0;                               ///< Link
    QString text;                               ///< Link: error text or description
    ContextSnapshot context;                    ///< Context
    quint64 droppedBytes = 0;                   ///< Dropped
    quint64 droppedChunks = 0;                  ///< Dropped

    static RecordEvent data(Kind kind, qint64 timeNs, const QByteArray &bytes)
    {
        RecordEvent e;
        e.kind = kind;
        e.timeNs = timeNs;
        e.bytes = bytes;
        return e;
    }
};

/// Why a recording could not be written or read, with the byte offset where that applies.
struct RecordingError {
    enum class Kind {
        None,
        OpenFailed,         ///< the file cannot be opened or created
        NotARecording,      ///< no recording magic
        UnsupportedVersion, ///< a format version this build does not read
        DamagedHeader,      ///< the header's checksum or layout is wrong
        Truncated,          ///< the file ends inside a block (a killed writer, a cut copy)
        Damaged,            ///< a block's checksum or layout is wrong
        DiskFull,           ///< no space left (ENOSPC, EDQUOT, file size limit)
        WriteFailed,        ///< any other write error
    };
    Kind kind = Kind::None;
    qint64 offset = -1; ///< byte offset of the damage, -1 where none applies
    QString message;    ///< a complete, translated sentence
    bool isError() const { return kind != Kind::None; }
};

} // namespace lk::recording

Q_DECLARE_METATYPE(lk::recording::RecordingError)
