#include "Command.h"

namespace lk::protocol {

namespace {
// Lengths follow the spec as corrected by docs/ERRATA.md: 0xA7 request LEN 4 (spec says 3),
// 0xA8 reply LEN 7 (spec says 8), 0x19 reply LEN 0 or 2, 0x12 reply LEN 42 or 58. The V2.35
// commands follow docs/V2.35.md section 4 (0x93 replies with an echo: the "8 byte" is a typo).
constexpr std::array<CommandInfo, CommandTable::kCount> kCommands{{
    {Command::ReadPid, "read_pid", 0, 6, -1, false, false, false, kOnV23},
    {Command::WritePidRam, "write_pid_ram", 6, 6, -1, true, false, false, kOnV23},
    {Command::WritePidRom, "write_pid_rom", 6, 6, -1, true, false, true, kOnV23},
    {Command::ReadAccel, "read_accel", 0, 4, -1, false, false, false, kOnV23},
    {Command::WriteAccelRam, "write_accel_ram", 4, 4, -1, true, false, false, kOnV23},
    {Command::ReadEncoder, "read_encoder", 0, 6, -1, false, false, false, kOnBoth},
    {Command::WriteEncoderOffset, "write_encoder_offset", 2, 2, -1, true, false, true, kOnV23},
    {Command::WriteZeroRom, "write_zero_rom", 0, 0, 2, true, false, true, kOnBoth},
    {Command::ReadMultiTurn, "read_multi_turn", 0, 8, -1, false, false, false, kOnBoth},
    {Command::ReadSingleTurn, "read_single_turn", 0, 4, -1, false, false, false, kOnBoth},
    {Command::ClearAngle, "clear_angle", 0, 0, -1, true, false, false, kOnBoth},
    {Command::ReadState1, "read_state1", 0, 7, -1, false, false, false, kOnBoth},
    {Command::ClearErrors, "clear_errors", 0, 7, -1, false, false, false, kOnBoth},
    {Command::ReadState2, "read_state2", 0, 7, -1, false, false, false, kOnBoth},
    {Command::ReadState3, "read_state3", 0, 7, -1, false, false, false, kOnBoth},
    {Command::MotorOff, "motor_off", 0, 0, -1, true, false, false, kOnBoth},
    {Command::MotorStop, "motor_stop", 0, 0, -1, true, false, false, kOnBoth},
    {Command::MotorRun, "motor_run", 0, 0, -1, true, true, false, kOnBoth},
    {Command::OpenLoop, "open_loop", 2, 7, -1, false, true, false, kOnBoth},
    {Command::Torque, "torque", 2, 7, -1, false, true, false, kOnBoth},
    {Command::Speed, "speed", 4, 7, -1, false, true, false, kOnBoth},
    {Command::MultiPosition, "multi_position", 8, 7, -1, false, true, false, kOnBoth},
    {Command::MultiPositionLimited, "multi_position_limited", 12, 7, -1, false, true, false,
     kOnBoth},
    {Command::SinglePosition, "single_position", 4, 7, -1, false, true, false, kOnBoth},
    {Command::SinglePositionLimited, "single_position_limited", 8, 7, -1, false, true, false,
     kOnBoth},
    {Command::IncrementPosition, "increment_position", 4, 7, -1, false, true, false, kOnBoth},
    {Command::IncrementPositionLimited, "increment_position_limited", 8, 7, -1, false, true, false,
     kOnBoth},
    {Command::ReadModel, "read_model", 0, 42, 58, false, false, false, kOnBoth},
    {Command::ReadParam, "read_param", 2, 7, -1, false, false, false, kOnV235},
    {Command::WriteParamRam, "write_param_ram", 7, 2, -1, false, false, false, kOnV235},
    {Command::WriteParamRom, "write_param_rom", 7, 2, -1, false, false, true, kOnV235},
    {Command::Brake, "brake", 1, 1, -1, false, false, false, kOnV235},
    {Command::ClearTurnCount, "clear_turn_count", 0, 0, -1, true, false, false, kOnV235},
    // CAN V2.36's control parameters (docs/CAN.md section 4.1): RAM only, never flash.
    {Command::ReadControlParam, "read_control_param", 7, 7, -1, false, false, false, kOnV235, true},
    {Command::WriteControlParam, "write_control_param", 7, 7, -1, false, false, false, kOnV235,
     true},
}};

// Dense code -> table index map, built once, so that the parser's lookup is O(1).
struct CodeIndex {
    std::array<qint8, 256> index{};
    CodeIndex()
    {
        index.fill(-1);
        for (int i = 0; i < CommandTable::kCount; ++i)
            index[static_cast<quint8>(kCommands[i].command)] = static_cast<qint8>(i);
    }
};
const CodeIndex &codeIndex()
{
    static const CodeIndex idx;
    return idx;
}
} // namespace

const std::array<CommandInfo, CommandTable::kCount> &CommandTable::all()
{
    return kCommands;
}

const CommandInfo *CommandTable::find(quint8 code)
{
    const qint8 i = codeIndex().index[code];
    return i < 0 ? nullptr : &kCommands[static_cast<size_t>(i)];
}

const CommandInfo &CommandTable::info(Command command)
{
    // A Command outside the table can only come from a cast; answer with an entry that
    // allows nothing rather than crash (movesMotor false, no lengths that match a frame).
    static const CommandInfo kUnknown{
        Command::ReadState2, "unknown", 0xFF, 0xFF, -1, false, false, false, 0};
    const CommandInfo *i = find(static_cast<quint8>(command));
    return i ? *i : kUnknown;
}

std::optional<Command> CommandTable::fromName(const QString &name)
{
    for (const CommandInfo &c : kCommands) {
        if (name == QLatin1String(c.name))
            return c.command;
    }
    return std::nullopt;
}

QString CommandTable::name(Command command)
{
    const CommandInfo *i = find(static_cast<quint8>(command));
    return i ? QString::fromLatin1(i->name) : codeText(static_cast<quint8>(command));
}

QString CommandTable::codeText(quint8 code)
{
    return QStringLiteral("0x%1")
        .arg(code, 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

bool CommandTable::availableOn(Command command, Generation generation)
{
    const CommandInfo *i = find(static_cast<quint8>(command));
    if (!i || i->canOnly)
        return false;
    return i->generations & (generation == Generation::V2_3 ? kOnV23 : kOnV235);
}

const CommandInfo *CommandTable::findOnRs485(quint8 code)
{
    const CommandInfo *i = find(code);
    return i && !i->canOnly ? i : nullptr;
}

bool CommandTable::availableOn(Command command, const DecodeContext &context)
{
    if (context.link == Link::Can && info(command).canOnly)
        return context.generation == Generation::V2_35 && find(quint8(command));
    if (!availableOn(command, context.generation))
        return false;
    if (context.link == Link::Rs485)
        return true;
    switch (command) {
    case Command::ReadModel:      // CAN has no model read in either generation
    case Command::ClearTurnCount: // CAN V2.36 clears the turn count with 0x80 instead
    case Command::ReadParam:      // CAN V2.36 has 0xC0/0xC1 in their place
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return false;
    case Command::ClearAngle:
        // The old CAN document marks 0x95 "not implemented": the drive echoes it and the
        // angle stays. On V2.36 it sets the position (to 0 for clear_angle).
        return context.generation == Generation::V2_35;
    default:
        return true;
    }
}

} // namespace lk::protocol
