#include "Command.h"

namespace lk::protocol {

namespace {
// Lengths follow the spec as corrected by ERRATA.md: 0xA7 request LEN 4 (spec says 3),
// 0xA8 reply LEN 7 (spec says 8), 0x19 reply LEN 0 or 2, 0x12 reply LEN 42 or 58.
constexpr std::array<CommandInfo, CommandTable::kCount> kCommands{{
    {Command::ReadPid, "read_pid", 0, 6, -1, false, false, false},
    {Command::WritePidRam, "write_pid_ram", 6, 6, -1, true, false, false},
    {Command::WritePidRom, "write_pid_rom", 6, 6, -1, true, false, true},
    {Command::ReadAccel, "read_accel", 0, 4, -1, false, false, false},
    {Command::WriteAccelRam, "write_accel_ram", 4, 4, -1, true, false, false},
    {Command::ReadEncoder, "read_encoder", 0, 6, -1, false, false, false},
    {Command::WriteEncoderOffset, "write_encoder_offset", 2, 2, -1, true, false, true},
    {Command::WriteZeroRom, "write_zero_rom", 0, 0, 2, true, false, true},
    {Command::ReadMultiTurn, "read_multi_turn", 0, 8, -1, false, false, false},
    {Command::ReadSingleTurn, "read_single_turn", 0, 4, -1, false, false, false},
    {Command::ClearAngle, "clear_angle", 0, 0, -1, true, false, false},
    {Command::ReadState1, "read_state1", 0, 7, -1, false, false, false},
    {Command::ClearErrors, "clear_errors", 0, 7, -1, false, false, false},
    {Command::ReadState2, "read_state2", 0, 7, -1, false, false, false},
    {Command::ReadState3, "read_state3", 0, 7, -1, false, false, false},
    {Command::MotorOff, "motor_off", 0, 0, -1, true, false, false},
    {Command::MotorStop, "motor_stop", 0, 0, -1, true, false, false},
    {Command::MotorRun, "motor_run", 0, 0, -1, true, true, false},
    {Command::OpenLoop, "open_loop", 2, 7, -1, false, true, false},
    {Command::Torque, "torque", 2, 7, -1, false, true, false},
    {Command::Speed, "speed", 4, 7, -1, false, true, false},
    {Command::MultiPosition, "multi_position", 8, 7, -1, false, true, false},
    {Command::MultiPositionLimited, "multi_position_limited", 12, 7, -1, false, true, false},
    {Command::SinglePosition, "single_position", 4, 7, -1, false, true, false},
    {Command::SinglePositionLimited, "single_position_limited", 8, 7, -1, false, true, false},
    {Command::IncrementPosition, "increment_position", 4, 7, -1, false, true, false},
    {Command::IncrementPositionLimited, "increment_position_limited", 8, 7, -1, false, true, false},
    {Command::ReadModel, "read_model", 0, 42, 58, false, false, false},
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
        Command::ReadState2, "unknown", 0xFF, 0xFF, -1, false, false, false};
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

} // namespace lk::protocol
