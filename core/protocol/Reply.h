#pragma once

#include "Command.h"
#include "Frame.h"
#include "Request.h"
#include "Series.h"
#include "Values.h"

#include <optional>
#include <variant>

namespace lk::protocol {

struct Acknowledged {}; ///< echo of a request without data (motor_off/stop/run, clear_angle)

/// The payload of a drive's reply, by command:
/// read_pid/write_pid_* -> PidGains; read_accel/write_accel_ram -> Acceleration;
/// read_encoder -> EncoderReading; write_encoder_offset -> EncoderOffset;
/// write_zero_rom -> ZeroWritten; read_multi_turn -> MultiTurnAngle;
/// read_single_turn -> SingleTurnAngle; read_state1/clear_errors -> State1;
/// read_state2 and 0xA0..0xA8 -> State2; read_state3 -> State3; read_model -> ModelInfo;
/// motor_off/stop/run, clear_angle, clear_turn_count -> Acknowledged; read_param ->
/// ParameterValue; write_param_ram/rom -> ParamWriteResult; brake -> BrakeState;
/// read_control_param/write_control_param -> ControlParameter (CAN V2.36: the value held, after
/// a write the value the drive took).
using ReplyPayload =
    std::variant<Acknowledged, PidGains, Acceleration, EncoderReading, EncoderOffset, ZeroWritten,
                 MultiTurnAngle, SingleTurnAngle, State1, State2, State3, ModelInfo, ParameterValue,
                 ParamWriteResult, BrakeState, ControlParameter>;

/// A typed drive -> host reply.
struct Reply {
    Command command = Command::ReadState2;
    quint8 id = 1;
    ReplyPayload payload;

    /// Encode as the drive would send it (the simulator's side). State2::isPower is not on
    /// the wire; ModelInfo::generation picks the 42- or 58-byte layout, State1::generation the
    /// 0x9A layout.
    Frame toFrame() const;
    QByteArray encode() const { return toFrame().encode(); }
};

struct ReplyDecodeResult {
    std::optional<Reply> reply;
    DecodeError error = DecodeError::None;
};

/// Decode a reply (or echo) frame. The context says whether torque fields are iq or power,
/// the generation picks the 0x9A/0x9B layout and the current scales, and the link the layout
/// (on CAN, `frame.data` is B1..B7: can::decodeReply).
/// A frame whose LEN is a request's (not a reply's) gives WrongDirection; short frames are
/// never decoded as zeros.
ReplyDecodeResult decodeReply(const Frame &frame, const DecodeContext &context = {});

} // namespace lk::protocol
