#pragma once

#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include "Series.h"

#include <array>
#include <optional>

namespace lk::protocol {

/// The commands of the LK RS485 protocol, both generations (V2.3 and V2.35), by wire code.
/// CommandInfo::generations says which generation has each one.
enum class Command : quint8 {
    ReadModel = 0x12,
    WriteZeroRom = 0x19,
    ReadPid = 0x30,
    WritePidRam = 0x31,
    WritePidRom = 0x32,
    ReadAccel = 0x33,
    WriteAccelRam = 0x34,
    ReadParam = 0x40,     ///< V2.35
    WriteParamRam = 0x42, ///< V2.35
    WriteParamRom = 0x44, ///< V2.35
    MotorOff = 0x80,
    MotorStop = 0x81,
    MotorRun = 0x88,
    Brake = 0x8C, ///< V2.35
    ReadEncoder = 0x90,
    WriteEncoderOffset = 0x91,
    ReadMultiTurn = 0x92,
    ClearTurnCount = 0x93, ///< V2.35
    ReadSingleTurn = 0x94,
    ClearAngle = 0x95,
    ReadState1 = 0x9A,
    ClearErrors = 0x9B,
    ReadState2 = 0x9C,
    ReadState3 = 0x9D,
    OpenLoop = 0xA0,
    Torque = 0xA1,
    Speed = 0xA2,
    MultiPosition = 0xA3,
    MultiPositionLimited = 0xA4,
    SinglePosition = 0xA5,
    SinglePositionLimited = 0xA6,
    IncrementPosition = 0xA7,
    IncrementPositionLimited = 0xA8,
    ReadControlParam = 0xC0,  ///< CAN V2.36 only
    WriteControlParam = 0xC1, ///< CAN V2.36 only, RAM
};

/// Which protocol generations have a command (a bit set of Generation).
enum GenerationMask : quint8 {
    kOnV23 = 0x1,
    kOnV235 = 0x2,
    kOnBoth = kOnV23 | kOnV235,
};

/// Static facts about one command: canonical name (CLI.md) and the data lengths it allows.
struct CommandInfo {
    Command command;
    const char *name;        ///< snake_case name from CLI.md, used in JSON, lkctl and the UI
    quint8 requestLength;    ///< LEN of the request the host sends
    quint8 replyLength;      ///< LEN of the drive's reply
    qint16 altReplyLength;   ///< a second accepted reply LEN (0x12: 58, 0x19: 2), or -1
    bool replyEchoesRequest; ///< the reply repeats the request byte for byte
    bool movesMotor;         ///< sending it can make the shaft move (0xA0..0xA8, 0x88)
    bool writesFlash;   ///< writes the drive's ROM (0x32, 0x91, 0x19, 0x44): ask first, never loop
    quint8 generations; ///< GenerationMask: V2.3-only 0x30..0x34 and 0x91, V2.35-only
                        ///< 0x40..0x44, 0x8C, 0x93 (docs/V2.35.md section 3)
    /// Only on CAN (V2.36's 0xC0/0xC1, docs/CAN.md): no RS485 drive has it, and an RS485
    /// frame with its code is an unknown command. The lengths are a CAN frame's B1..B7.
    bool canOnly = false;
};

/// The command table: lookup by code or by name.
class CommandTable {
public:
    static constexpr int kCount = 35;
    static const std::array<CommandInfo, kCount> &all();
    static const CommandInfo *find(quint8 code);
    /// Facts about a command; a value outside the table (a cast) gets an entry named
    /// "unknown" whose lengths match no frame.
    static const CommandInfo &info(Command command);
    /// The CLI.md name, or "0x93" for a value outside the table.
    static std::optional<Command> fromName(const QString &name);
    static QString name(Command command);
    static QString codeText(quint8 code); ///< "0xA2"
    /// Whether an RS485 drive of `generation` has `command` (nothing it lacks is ever sent to
    /// it); never a CAN-only command.
    static bool availableOn(Command command, Generation generation);
    /// Whether a drive of `context`'s link and generation has `command`: on CAN there is no
    /// 0x12, 0x93 or 0x40..0x44; the old CAN generation has no working 0x95; only CAN V2.36
    /// has 0xC0/0xC1 (docs/CAN.md).
    static bool availableOn(Command command, const DecodeContext &context);
    /// The command of an RS485 frame's code: nullptr for codes outside the table and for the
    /// CAN-only ones.
    static const CommandInfo *findOnRs485(quint8 code);
};

} // namespace lk::protocol
