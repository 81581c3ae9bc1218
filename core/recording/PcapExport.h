#pragma once

#include "RecordingReader.h"

#include <protocol/CanRecord.h>

#include <QtCore/QIODevice>

namespace lk::recording {

/// A recording as a pcap file for Wireshark (docs/RECORDING.md "The pcap encapsulation"):
/// link type USER0, one packet per frame (or run of bytes that formed none), each behind a
/// 2-byte pseudo-header: wire direction (0 rx, 1 tx) and frame direction (0 request, 1 reply,
/// 2 echo, 3 no frame, 4 decode context). A context packet (first, and wherever the recording's
/// context changes) carries (id, series, generation) byte triples as in the recording format,
/// so the dissector decodes MS power and V2.35 layouts as the tool did.
/// packaging/wireshark/lkservo.lua dissects it. A CAN recording is written with the SocketCAN
/// link type instead, one packet per CAN frame.
class PcapExport {
public:
    static constexpr quint32 kLinkType = 147; ///< LINKTYPE_USER0
    /// A recording made on CAN: Wireshark's own CAN dissector reads struct can_frame.
    static constexpr quint32 kLinkTypeSocketCan = 227; ///< LINKTYPE_CAN_SOCKETCAN
    enum class FrameKind : quint8 { Request = 0, Reply = 1, Echo = 2, NoFrame = 3, Context = 4 };

    static QByteArray fileHeader(quint32 linkType = kLinkType);
    /// One packet record; `unixNs`: its wall-clock time.
    static QByteArray packet(qint64 unixNs, bool transmitted, FrameKind kind,
                             const QByteArray &bytes);

    /// One LINKTYPE_CAN_SOCKETCAN packet: struct can_frame (the ID in network byte order
    /// with CAN_EFF_FLAG / CAN_ERR_FLAG, the DLC, 3 bytes 0, 8 data bytes zero-padded).
    static QByteArray socketCanPacket(qint64 unixNs, const protocol::CanRecord &record);

    /// Write every frame of the reader's recording (from its current place) to `out`; a
    /// recording made on CAN as LINKTYPE_CAN_SOCKETCAN (what the tool sent, what it received
    /// but for its own frames looped back, error frames). Returns the packet count; reading
    /// stops at damage (reader.error() says where).
    static qint64 write(RecordingReader &reader, QIODevice &out);
};

} // namespace lk::recording
