#include "CanFrameTime.h"

#include "CanLayout.h"

namespace lk::protocol::can {

namespace {
// A base-format data frame: SOF 1, identifier 11, RTR 1, IDE 1, r0 1, DLC 4, data 8n,
// CRC 15, CRC delimiter 1, ACK 2, EOF 7, interframe space 3.
constexpr int kFixedBits = 47;
// Stuffing covers SOF..CRC: 34 + 8n bits, at most one stuff bit per four after the first.
constexpr int kStuffedRegionFixedBits = 34;
} // namespace

int frameBits(int dataBytes)
{
    return kFixedBits + 8 * dataBytes;
}

int frameBitsStuffed(int dataBytes)
{
    const int stuffed = kStuffedRegionFixedBits + 8 * dataBytes;
    return frameBits(dataBytes) + (stuffed - 1) / 4;
}

double frameSeconds(int bitRate)
{
    return bitRate > 0 ? static_cast<double>(frameBitsStuffed(kDataSize)) / bitRate : 0.0;
}

} // namespace lk::protocol::can
