#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QtGlobal>

#include <optional>

namespace lk::protocol {

/// Which way a frame travels, as far as its layout tells (CLI.md).
enum class FrameDirection {
    Request, ///< host -> drive
    Reply,   ///< drive -> host
    Echo,    ///< the drive's reply repeats the request: both directions carry these bytes
};

/// One well-formed frame (both checksums valid): 3E CMD ID LEN HCS [DATA..., DCS].
struct Frame {
    quint8 command = 0;
    quint8 id = 0;
    QByteArray data; ///< exactly LEN bytes, without the data checksum

    /// The bytes on the wire, checksums included.
    QByteArray encode() const;
    /// Request, reply or echo from the command table; nullopt when LEN fits neither
    /// (or the command is unknown).
    std::optional<FrameDirection> direction() const;

    bool operator==(const Frame &o) const
    {
        return command == o.command && id == o.id && data == o.data;
    }
};

QByteArray encodeFrame(quint8 command, quint8 id, const QByteArray &data);
const char *directionName(FrameDirection d); ///< "request", "reply", "echo"

} // namespace lk::protocol
