#pragma once

#include "CanLayout.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include <optional>

namespace lk::protocol {

/// One CAN frame as the CAN transport moves it: a fixed 23-byte, versioned record, so that
/// every transport keeps carrying "bytes" (docs/CAN.md, "The record"). Little-endian:
/// `u8 version | u32 CAN ID | u8 flags | u8 DLC | 8 data bytes | i64 timestamp in µs`.
/// Data bytes beyond the DLC are 0.
struct CanRecord {
    static constexpr quint8 kVersion = 1;
    static constexpr int kSize = 23;
    static constexpr int kMaxData = 8;
    enum Flag : quint8 {
        Echo = 0x01,     ///< our own frame, looped back by the adapter
        Error = 0x02,    ///< an error frame: the ID holds the error class, the data its detail
        Extended = 0x04, ///< a 29-bit identifier
    };
    static constexpr quint8 kKnownFlags = Echo | Error | Extended;

    quint32 canId = 0;
    quint8 flags = 0;
    QByteArray data; ///< 0..8 bytes: the DLC is its size
    qint64 timestampUs = 0;

    bool isEcho() const { return flags & Echo; }
    bool isError() const { return flags & Error; }
    bool isExtended() const { return flags & Extended; }

    QByteArray encode() const;
    /// The record at `bytes` (at least kSize of them); nullopt for another version, an
    /// unknown flag or a DLC over 8.
    static std::optional<CanRecord> decode(const char *bytes);
    static std::optional<CanRecord> decode(const QByteArray &bytes);
    /// A data frame from the codec.
    static CanRecord of(const can::CanData &data, qint64 timestampUs = 0);
    can::CanData canData() const { return can::CanData{canId, data}; }
    /// The frame in candump notation: "141#9C00000000000000" (a 29-bit ID has 8 digits).
    QString candumpText() const;
    /// One line of a `candump -L` log, which can-utils, python-can and SavvyCAN read:
    /// "(1700000000.123456) can0 141#9C00000000000000". Error frames carry the CAN_ERR_FLAG
    /// (0x20000000) in their 8-digit ID, as candump writes them.
    QString candumpLogLine(const QString &interfaceName) const;
    /// A frame in candump notation, bare ("141#9C00") or as a `candump -L` line; nullopt for
    /// anything else (remote and CAN FD frames included). The interface name is not kept.
    static std::optional<CanRecord> fromCandump(const QString &text);

    bool operator==(const CanRecord &o) const
    {
        return canId == o.canId && flags == o.flags && data == o.data &&
               timestampUs == o.timestampUs;
    }
};

} // namespace lk::protocol
