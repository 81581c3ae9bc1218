#pragma once

namespace lk::protocol::can {

// How long a classic CAN frame occupies the wire: what the bus limit, the timeouts and the
// simulator's wire time are built on. The layouts of the bytes it carries are CanLayout's.

/// Bits of a classic base-format data frame with `dataBytes` bytes, interframe space
/// included: 47 + 8 n.
int frameBits(int dataBytes);
/// The same with the most stuff bits the frame can carry: one per four bits of SOF..CRC.
int frameBitsStuffed(int dataBytes);
/// Seconds one LK frame (8 data bytes, worst-case stuffing) takes at `bitRate`.
double frameSeconds(int bitRate);

} // namespace lk::protocol::can
