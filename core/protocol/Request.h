#pragma once

#include "Command.h"
#include "ControlParameter.h"
#include "FieldError.h"
#include "Frame.h"
#include "Parameter.h"
#include "Values.h"

#include <optional>
#include <variant>

namespace lk::protocol {

struct NoPayload {};

/// The payload of a request, by command: empty for reads and off/stop/run; read_param ->
/// ParamRead; write_param_ram/rom -> ParameterValue; brake -> BrakeCommand;
/// read_control_param -> ControlParamRead; write_control_param -> ControlParameter (CAN V2.36).
using RequestPayload =
    std::variant<NoPayload, PidGains, Acceleration, EncoderOffset, OpenLoopCommand, TorqueCommand,
                 SpeedCommand, MultiPositionCommand, SinglePositionCommand,
                 IncrementPositionCommand, ParamRead, ParameterValue, BrakeCommand,
                 ControlParamRead, ControlParameter, PositionSet>;

/// A host -> drive request. Built with the functions in RequestBuilder.h it has passed the
/// wire ranges of the spec and ERRATA; read back with decodeRequest() it holds the values as
/// received, unchecked (a drive, or the simulator, must not trust them).
struct Request {
    Command command = Command::ReadState2;
    quint8 id = 1;
    RequestPayload payload;

    Frame toFrame() const;
    QByteArray encode() const { return toFrame().encode(); }
};

/// Outcome of building a request: the request, or the field that was out of range.
struct BuildResult {
    std::optional<Request> request;
    FieldError error;
    bool ok() const { return request.has_value(); }
};

/// Why a frame could not be read as a typed request or reply.
enum class DecodeError { None, UnknownCommand, BadLength, WrongDirection };

/// A request frame read back into its typed form (the simulator and `lkctl decode` use it).
/// Only the LEN is checked; a single-turn direction byte other than 0 reads as CCW.
struct RequestDecodeResult {
    std::optional<Request> request;
    DecodeError error = DecodeError::None;
};
RequestDecodeResult decodeRequest(const Frame &frame);
/// The same on `context.link`: on CAN, `frame.data` is B1..B7 (can::decodeRequest).
RequestDecodeResult decodeRequest(const Frame &frame, const DecodeContext &context);

/// `[ParamID, six value bytes]` (0x40 reply, 0x42/0x44 request) as a ParameterValue; `d`
/// holds at least 7 bytes.
ParameterValue readParameter(const QByteArray &d);

} // namespace lk::protocol
