#pragma once

#include <QtCore/QtGlobal>

namespace lk::recording {

/// CRC-32 (IEEE 802.3, the zlib/PNG polynomial): every block of a recording carries one, so a
/// damaged byte is found. `crc` continues an earlier call (start with 0).
quint32 crc32(const char *data, qsizetype size, quint32 crc = 0);

} // namespace lk::recording
