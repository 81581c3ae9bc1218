#include "CommandTitle.h"

#include <iterator>

namespace lk::text {

using protocol::Command;

namespace {

struct Title {
    Command command;
    const char *text;
};

// Every command of protocol::CommandTable, in wire-code order (tst_commandtitle checks that
// none is missing).
constexpr Title kTitles[] = {
    {Command::ReadModel, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read model")},
    {Command::WriteZeroRom,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write the position as zero to ROM")},
    {Command::ReadPid, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read PID gains")},
    {Command::WritePidRam, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write PID gains to RAM")},
    {Command::WritePidRom, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write PID gains to ROM")},
    {Command::ReadAccel, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read acceleration")},
    {Command::WriteAccelRam,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write acceleration to RAM")},
    {Command::ReadParam, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read parameter")},
    {Command::WriteParamRam, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write parameter to RAM")},
    {Command::WriteParamRom, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write parameter to ROM")},
    {Command::MotorOff, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Motor Off")},
    {Command::MotorStop, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Motor Stop")},
    {Command::MotorRun, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Motor Run")},
    {Command::Brake, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Brake control")},
    {Command::ReadEncoder, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read encoder")},
    {Command::WriteEncoderOffset,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write encoder offset to ROM")},
    {Command::ReadMultiTurn, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read multi-turn angle")},
    {Command::ClearTurnCount, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Clear turn count")},
    {Command::ReadSingleTurn,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read single-turn angle")},
    {Command::ClearAngle, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Clear angle")},
    {Command::ReadState1,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read state 1 (temperature, voltage, errors)")},
    {Command::ClearErrors, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Clear errors")},
    {Command::ReadState2,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read state 2 (current, speed, encoder)")},
    {Command::ReadState3,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read state 3 (phase currents)")},
    {Command::OpenLoop, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Open loop power")},
    {Command::Torque, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Torque current")},
    {Command::Speed, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Speed")},
    {Command::MultiPosition, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Multi-turn position")},
    {Command::MultiPositionLimited,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Multi-turn position with speed limit")},
    {Command::SinglePosition, QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Single-turn position")},
    {Command::SinglePositionLimited,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Single-turn position with speed limit")},
    {Command::IncrementPosition,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Incremental position")},
    {Command::IncrementPositionLimited,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Incremental position with speed limit")},
    {Command::ReadControlParam,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Read control parameter")},
    {Command::WriteControlParam,
     QT_TRANSLATE_NOOP("lk::text::CommandTitle", "Write control parameter to RAM")},
};
static_assert(std::size(kTitles) == protocol::CommandTable::kCount,
              "a command of the table has no title");

} // namespace

QString CommandTitle::name(Command command)
{
    for (const Title &t : kTitles) {
        if (t.command == command)
            return tr(t.text);
    }
    return protocol::CommandTable::codeText(quint8(command));
}

QString CommandTitle::withCode(Command command)
{
    return QStringLiteral("%1 (%2)").arg(name(command),
                                         protocol::CommandTable::codeText(quint8(command)));
}

QString CommandTitle::multiTorque()
{
    return tr("Multi-motor torque (0x280)");
}

} // namespace lk::text
