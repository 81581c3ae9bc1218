#include "Crc32.h"

#include <array>

namespace lk::recording {

namespace {

// Slicing-by-8 (Intel's method, as zlib does it): eight tables, eight bytes per step. The
// reader checks every block of an hour-long recording when it is opened and played, and the
// bytewise loop was the largest single cost of that.
using Tables = std::array<std::array<quint32, 256>, 8>;

Tables makeTables()
{
    Tables t{};
    for (quint32 i = 0; i < 256; ++i) {
        quint32 c = i;
        for (int k = 0; k < 8; ++k)
            c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        t[0][i] = c;
    }
    for (quint32 i = 0; i < 256; ++i) {
        for (size_t s = 1; s < t.size(); ++s)
            t[s][i] = t[0][t[s - 1][i] & 0xFF] ^ (t[s - 1][i] >> 8);
    }
    return t;
}

quint32 le32(const uchar *p)
{
    return quint32(p[0]) | quint32(p[1]) << 8 | quint32(p[2]) << 16 | quint32(p[3]) << 24;
}

} // namespace

quint32 crc32(const char *data, qsizetype size, quint32 crc)
{
    static const Tables t = makeTables();
    const auto *p = reinterpret_cast<const uchar *>(data);
    crc = ~crc;
    for (; size >= 8; size -= 8, p += 8) {
        const quint32 lo = crc ^ le32(p);
        const quint32 hi = le32(p + 4);
        crc = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
              t[3][hi & 0xFF] ^ t[2][(hi >> 8) & 0xFF] ^ t[1][(hi >> 16) & 0xFF] ^ t[0][hi >> 24];
    }
    for (; size > 0; --size, ++p)
        crc = t[0][(crc ^ *p) & 0xFF] ^ (crc >> 8);
    return ~crc;
}

} // namespace lk::recording
