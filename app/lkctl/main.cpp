#include "BackupCommand.h"
#include "BrakeCommand.h"
#include "ClearErrorsCommand.h"
#include "Console.h"
#include "ControlCommand.h"
#include "DecodeCommand.h"
#include "DiffCommand.h"
#include "Dispatcher.h"
#include "EncodeCommand.h"
#include "ExportCommand.h"
#include "FreqCommand.h"
#include "InfoCommand.h"
#include "ListenCommand.h"
#include "MonitorCommand.h"
#include "MotorStateCommand.h"
#include "ReadCommand.h"
#include "ReplayCommand.h"
#include "RestoreCommand.h"
#include "ScanCommand.h"
#include "StepCommand.h"
#include "TuneCommand.h"
#include "WriteCommand.h"
#include "ZeroCommand.h"

#include <text/VerdictText.h>

#include <system/LocalTimeZone.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QLoggingCategory>

#include <memory>

int main(int argc, char *argv[])
{
    lk::system::LocalTimeZone::readOnce(); // before any thread: Qt's CAN plugins stamp frames
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("lkctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LK_VERSION));

    // lkctl prints its own messages (with the fix where there is one): the engine's logging
    // would repeat them. QT_LOGGING_RULES still turns it back on for a diagnosis.
    QLoggingCategory::setFilterRules(QStringLiteral("lk.*.info=false\nlk.*.warning=false"));
    // A refusal names the command as the command line does ("open_loop"), not by the GUI's title.
    lk::text::VerdictText::setCommandNames(lk::text::VerdictText::CommandNames::Cli);

    lk::lkctl::Console console;
    lk::lkctl::Dispatcher dispatcher(QStringLiteral("lkctl"), QStringLiteral(LK_VERSION));
    using lk::protocol::Command;
    using namespace lk::lkctl;
    dispatcher.add(std::make_unique<ScanCommand>());
    dispatcher.add(std::make_unique<InfoCommand>());
    dispatcher.add(std::make_unique<ReadCommand>());
    dispatcher.add(std::make_unique<WriteCommand>());
    dispatcher.add(std::make_unique<ControlCommand>());
    dispatcher.add(std::make_unique<MotorStateCommand>(Command::MotorOff));
    dispatcher.add(std::make_unique<MotorStateCommand>(Command::MotorStop));
    dispatcher.add(std::make_unique<MotorStateCommand>(Command::MotorRun));
    dispatcher.add(std::make_unique<BrakeCommand>());
    dispatcher.add(std::make_unique<ClearErrorsCommand>());
    dispatcher.add(std::make_unique<ZeroCommand>(ZeroCommand::Kind::Zero));
    dispatcher.add(std::make_unique<ZeroCommand>(ZeroCommand::Kind::ClearTurns));
    dispatcher.add(std::make_unique<StepCommand>());
    dispatcher.add(std::make_unique<FreqCommand>());
    dispatcher.add(std::make_unique<TuneCommand>());
    dispatcher.add(std::make_unique<MonitorCommand>());
    dispatcher.add(std::make_unique<ListenCommand>());
    dispatcher.add(std::make_unique<BackupCommand>());
    dispatcher.add(std::make_unique<DiffCommand>());
    dispatcher.add(std::make_unique<RestoreCommand>(RestoreCommand::Kind::Restore));
    dispatcher.add(std::make_unique<RestoreCommand>(RestoreCommand::Kind::Clone));
    dispatcher.add(std::make_unique<EncodeCommand>());
    dispatcher.add(std::make_unique<DecodeCommand>());
    dispatcher.add(std::make_unique<ExportCommand>());
    dispatcher.add(std::make_unique<ReplayCommand>());
    return dispatcher.run(QCoreApplication::arguments().mid(1), console);
}
