#pragma once

#include "ControlParameter.h"
#include "FieldError.h"
#include "Frame.h"
#include "Reply.h"
#include "Request.h"
#include "Series.h"

#include <QtCore/QByteArray>
#include <QtCore/QtGlobal>

#include <array>
#include <optional>

namespace lk::protocol::can {

// The 8-byte layouts of LK drives on CAN, both generations (docs/CAN.md). A CAN frame maps
// onto the codec's Frame as {command = B0, id = from the arbitration ID, data = B1..B7}, so
// everything that reads Frames (matching, traffic, telemetry) works on CAN unchanged; only
// the layouts of B1..B7 differ from RS485, and they live here.

constexpr int kDataSize = 8;              ///< classic CAN, always DLC 8, unused bytes 0x00
constexpr quint32 kRequestBase = 0x140;   ///< request 0x140 + ID; old replies too
constexpr quint32 kReplyBaseV236 = 0x180; ///< the V2.36 document's reply ID (never seen)
constexpr quint32 kMultiMotorId = 0x280;  ///< torque for IDs 1..4 in one frame (old CAN)
constexpr int kMultiMotorDrives = 4;
constexpr qint16 kMultiMotorIqMax = 2000; ///< +-2000 = +-32 A per the old CAN document
constexpr qint16 kSpeedIqLimitMax = 2048; ///< V2.36 0xA2 torque limit, iq units

/// Which of the two documented ID bases a frame travels on.
enum class IdBase {
    Base140, ///< every request; the old generation's replies (and V2.36 replies seen in practice)
    Base180, ///< replies as the V2.36 document describes them
};

/// The drive an arbitration ID belongs to: 0x141..0x160 or 0x181..0x1A0.
struct DriveAddress {
    quint8 driveId = 0;
    IdBase base = IdBase::Base140;
};
std::optional<DriveAddress> driveAddressOf(quint32 canId);

quint32 requestCanId(quint8 driveId);
/// The ID a drive of `generation` answers on per its document: 0x140+ID (old), 0x180+ID
/// (V2.36). A host accepts both (driveAddressOf), as no hardware has been seen to use 0x180.
quint32 replyCanId(quint8 driveId, Generation generation);

/// One classic CAN data frame: an 11-bit arbitration ID and its 8 data bytes.
struct CanData {
    quint32 canId = 0;
    QByteArray bytes; ///< B0..B7
    bool operator==(const CanData &o) const { return canId == o.canId && bytes == o.bytes; }
};

/// A CAN frame encoded from a typed value, or the reason it cannot be sent on this dialect.
struct CanEncodeResult {
    std::optional<CanData> data;
    FieldError error;
    bool ok() const { return data.has_value(); }
};

/// The frame a host sends for `request` on `context`'s CAN generation. Refused, with the
/// field named: a command the generation lacks, a multi-turn angle beyond int32, a max
/// speed under 1 dps (CAN carries uint16 1 dps, rounded down), a single-turn angle beyond
/// the generation's field, and a V2.36 0xA2 without a torque limit.
CanEncodeResult encodeRequest(const Request &request, const DecodeContext &context);
/// The frame a drive of `context` answers `reply` with (the simulator's side), on its
/// documented reply ID.
CanEncodeResult encodeReply(const Reply &reply, const DecodeContext &context);

/// {B0, drive ID, B1..B7}; nullopt for an ID that is no drive's or data that is not 8 bytes.
std::optional<Frame> frameOf(const CanData &data);
/// B0..B7 of a frame whose data is B1..B7.
QByteArray bytesOf(const Frame &frame);

/// A request frame (B1..B7 in `frame.data`) in its typed form; BadLength unless 7 bytes.
RequestDecodeResult decodeRequest(const Frame &frame, const DecodeContext &context);
/// A reply frame (B1..B7 in `frame.data`) in its typed form; BadLength unless 7 bytes. The
/// 0x92 angle is sign-extended from bit 55 of its seven bytes.
ReplyDecodeResult decodeReply(const Frame &frame, const DecodeContext &context);

/// What one reply says about the CAN generation of its drive, where it says anything
/// (docs/CAN.md section 9): a reply on 0x180+ID is V2.36; a 0x9A/0x9B reply is read both ways
/// and names a generation when only one reading is plausible (old: B2, B5 and B6 zero and
/// B3-B4 a supply of 6..60 V in 0.1 V; V2.36: B2-B3 a supply of 6..60 V in 0.01 V and B6 0x00
/// or 0x10). nullopt when the reply cannot tell.
std::optional<Generation> generationHint(const CanData &reply);

/// The old generation's multi-motor torque frame (0x280): iq for drives 1..4, each
/// -2000..2000. Refused with the drive named when a value is out of range.
CanEncodeResult encodeMultiMotorTorque(const std::array<qint16, kMultiMotorDrives> &iqRaw);
std::optional<std::array<qint16, kMultiMotorDrives>> decodeMultiMotorTorque(const CanData &data);

/// CAN V2.36 0x95: the current position becomes `angleRaw` (0.01 deg, RAM). clear_angle is
/// the same frame with 0.
CanData encodeSetPosition(quint8 driveId, qint32 angleRaw);
/// The position a V2.36 0x95 frame sets; nullopt for any other frame.
std::optional<qint32> decodeSetPosition(const CanData &data);

/// The CAN V2.36 control parameters of 0xC0 (read) and 0xC1 (write, RAM only), docs/CAN.md.
using protocol::ControlParameter;
using protocol::ControlParamId;
constexpr quint8 kReadControlParam = 0xC0;
constexpr quint8 kWriteControlParam = 0xC1;

CanData encodeControlParamRead(quint8 driveId, ControlParamId param);
CanData encodeControlParamWrite(quint8 driveId, const ControlParameter &value);
/// A 0xC0 reply or 0xC1 request/reply; nullopt for any other frame.
std::optional<ControlParameter> decodeControlParam(const CanData &data);

} // namespace lk::protocol::can
