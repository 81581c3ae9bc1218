#pragma once

#include <QtCore/QtGlobal>

namespace lk::recording::tags {

// The first byte of a record (docs/RECORDING.md "Records").
inline constexpr quint8 kMeta = 0x80;  ///< set: a meta record, type in the low 7 bits
inline constexpr quint8 kTxBit = 0x40; ///< data record: transmitted (else received)
inline constexpr quint8 kLengthMask = 0x3F;
inline constexpr qsizetype kMaxInlineLength = 63; ///< data lengths 1..63 fit in the tag
inline constexpr quint8 kLink = 1;
inline constexpr quint8 kContext = 2;
inline constexpr quint8 kDropped = 3;

} // namespace lk::recording::tags
