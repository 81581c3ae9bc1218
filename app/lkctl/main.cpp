#include "Console.h"
#include "DecodeCommand.h"
#include "Dispatcher.h"
#include "EncodeCommand.h"

#include <QtCore/QCoreApplication>

#include <memory>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("lkctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LK_VERSION));

    lk::lkctl::Console console;
    lk::lkctl::Dispatcher dispatcher(QStringLiteral("lkctl"), QStringLiteral(LK_VERSION));
    // One line per subcommand: scan, info, read, write, control, off/stop/run and monitor
    // join here.
    dispatcher.add(std::make_unique<lk::lkctl::EncodeCommand>());
    dispatcher.add(std::make_unique<lk::lkctl::DecodeCommand>());
    return dispatcher.run(QCoreApplication::arguments().mid(1), console);
}
