#pragma once

#include "Frame.h"
#include "Series.h"

#include <QtCore/QByteArray>

#include <functional>
#include <memory>
#include <optional>

namespace lk::protocol {

/// What went wrong with some bytes of a stream (names as in CLI.md).
enum class ParseError {
    BadHeaderChecksum,
    BadDataChecksum,
    BadLength,      ///< LEN over 60, or a LEN the command never carries (checksums were fine)
    UnknownCommand, ///< checksums fine, command code not in the table
    Garbage,        ///< bytes skipped while looking for the next 0x3E
    Truncated,      ///< the stream ended inside a frame
};
const char *parseErrorName(ParseError e); ///< "bad_header_checksum", ...

/// One result of parsing: a valid frame, or a fault with the bytes it covers.
struct ParseEvent {
    bool isFrame = false;
    Frame frame; ///< set for frames, and for UnknownCommand/BadLength (checksums were valid)
    FrameDirection direction = FrameDirection::Request; ///< meaningful when isFrame
    ParseError error = ParseError::Garbage;             ///< meaningful when !isFrame
    QByteArray bytes;                                   ///< the raw bytes this event consumed
    /// CAN parser only: the arbitration ID the frame came on (0x140+ID or 0x180+ID), which
    /// tells the drive's generation apart (docs/CAN.md section 9). Unset on RS485.
    std::optional<quint32> canId;
    /// CAN parser only: the transport flagged the record as our own frame looped back. The
    /// reply matcher takes this flag, not a byte comparison, for the local echo.
    bool echoed = false;
};

/// Turns what a transport delivers into frames and faults, one implementation per link: the
/// RS485 byte stream (StreamParser) and the CAN transport's records (CanRecordParser). Both
/// emit ParseEvents, so matching, traffic and statistics read every link the same way.
class FrameParser {
public:
    using Sink = std::function<void(const ParseEvent &)>;

    virtual ~FrameParser() = default;
    virtual void feed(const char *data, qsizetype size, const Sink &sink) = 0;
    /// The same, from a QByteArray a parser may share rather than copy.
    virtual void feed(const QByteArray &bytes, const Sink &sink)
    {
        feed(bytes.constData(), bytes.size(), sink);
    }
    /// End of stream: what is pending is reported.
    virtual void finish(const Sink &sink) = 0;
    /// Drop pending bytes without reporting them (e.g. after reopening a port).
    virtual void reset() = 0;
    virtual qsizetype pendingBytes() const = 0;
};

/// Which end of the link a parser sits on: it decides the direction of a CAN frame on
/// 0x140+ID, which carries both requests and (old generation) replies.
enum class LinkEnd {
    Host,  ///< the tool: what arrives is a reply, unless the adapter echoes our own frame
    Drive, ///< the simulator: what arrives on 0x140+ID is a request
};

/// The parser for `link`.
std::unique_ptr<FrameParser> makeFrameParser(Link link, LinkEnd end = LinkEnd::Host);

} // namespace lk::protocol
