#pragma once

#include <QtCore/QtGlobal>

namespace lk::protocol {

/// Frame constants and the two checksums of the LK RS485 frame.
/// Checksums are the byte sum & 0xFF, never % 255 (docs/ERRATA.md: drives ignore % 255 frames).
constexpr quint8 kFrameHead = 0x3E;
constexpr int kHeaderSize = 5;     ///< 3E CMD ID LEN HCS
constexpr int kMaxDataLength = 60; ///< spec: data 0..60 bytes
constexpr int kMaxFrameSize = kHeaderSize + kMaxDataLength + 1;
constexpr int kMinId = 1;
constexpr int kMaxId = 32;

inline quint8 byteSum(const char *data, qsizetype n)
{
    unsigned sum = 0;
    for (qsizetype i = 0; i < n; ++i)
        sum += static_cast<quint8>(data[i]);
    return static_cast<quint8>(sum & 0xFFu);
}

inline quint8 headerChecksum(quint8 cmd, quint8 id, quint8 len)
{
    return static_cast<quint8>((kFrameHead + cmd + id + len) & 0xFFu);
}

} // namespace lk::protocol
