#pragma once

#include <QtCore/QByteArray>

namespace lk::recording {

/// LEB128 unsigned varints and little-endian fixed integers, as docs/RECORDING.md uses them.
namespace varint {

inline void put(QByteArray &out, quint64 v)
{
    while (v >= 0x80) {
        out.append(char(quint8(v) | 0x80));
        v >>= 7;
    }
    out.append(char(v));
}

/// Reads one varint at `pos` (advanced past it); false when it runs past `end` or is longer
/// than 10 bytes.
inline bool get(const char *data, qsizetype end, qsizetype &pos, quint64 &v)
{
    v = 0;
    for (int shift = 0; shift < 70 && pos < end; shift += 7) {
        const quint8 b = quint8(data[pos++]);
        v |= quint64(b & 0x7F) << shift;
        if (!(b & 0x80))
            return true;
    }
    return false;
}

template <typename T> void putFixed(QByteArray &out, T v)
{
    for (unsigned i = 0; i < sizeof(T); ++i)
        out.append(char(quint8(quint64(v) >> (8 * i))));
}

template <typename T> T getFixed(const char *data)
{
    quint64 v = 0;
    for (unsigned i = 0; i < sizeof(T); ++i)
        v |= quint64(quint8(data[i])) << (8 * i);
    return T(v);
}

} // namespace varint
} // namespace lk::recording
