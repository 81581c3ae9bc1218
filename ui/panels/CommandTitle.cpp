#include "CommandTitle.h"

#include <iterator>

namespace lk::ui {

using protocol::Command;

namespace {

struct Title {
    Command command;
    const char *text;
};

// Every command of protocol::CommandTable, in wire-code order (tst_commandtitle checks that
// none is missing).
constexpr Title kTitles[] = {
    {Command::ReadModel, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read model")},
    {Command::WriteZeroRom,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write the position as zero to ROM")},
    {Command::ReadPid, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read PID gains")},
    {Command::WritePidRam, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write PID gains to RAM")},
    {Command::WritePidRom, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write PID gains to ROM")},
    {Command::ReadAccel, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read acceleration")},
    {Command::WriteAccelRam,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write acceleration to RAM")},
    {Command::ReadParam, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read parameter")},
    {Command::WriteParamRam, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write parameter to RAM")},
    {Command::WriteParamRom, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write parameter to ROM")},
    {Command::MotorOff, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Motor Off")},
    {Command::MotorStop, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Motor Stop")},
    {Command::MotorRun, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Motor Run")},
    {Command::Brake, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Brake control")},
    {Command::ReadEncoder, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read encoder")},
    {Command::WriteEncoderOffset,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Write encoder offset to ROM")},
    {Command::ReadMultiTurn, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read multi-turn angle")},
    {Command::ClearTurnCount, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Clear turn count")},
    {Command::ReadSingleTurn, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read single-turn angle")},
    {Command::ClearAngle, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Clear angle")},
    {Command::ReadState1,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read state 1 (temperature, voltage, errors)")},
    {Command::ClearErrors, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Clear errors")},
    {Command::ReadState2,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read state 2 (current, speed, encoder)")},
    {Command::ReadState3,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Read state 3 (phase currents)")},
    {Command::OpenLoop, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Open loop power")},
    {Command::Torque, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Torque current")},
    {Command::Speed, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Speed")},
    {Command::MultiPosition, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Multi-turn position")},
    {Command::MultiPositionLimited,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Multi-turn position with speed limit")},
    {Command::SinglePosition, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Single-turn position")},
    {Command::SinglePositionLimited,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Single-turn position with speed limit")},
    {Command::IncrementPosition, QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Incremental position")},
    {Command::IncrementPositionLimited,
     QT_TRANSLATE_NOOP("lk::ui::CommandTitle", "Incremental position with speed limit")},
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

} // namespace lk::ui
