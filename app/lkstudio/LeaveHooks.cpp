#include "LeaveHooks.h"

#include "DemoMotion.h"

#include <main/LeaveGuard.h>
#include <main/MainWindow.h>

#include <system/SignalWatcher.h>

#include <QtGui/QGuiApplication>
#include <QtGui/QSessionManager>

void LeaveHooks::closeOnTermination(lk::ui::MainWindow &window, lk::system::SignalWatcher &watcher)
{
    QObject::connect(&watcher, &lk::system::SignalWatcher::signalled, &window,
                     &lk::ui::MainWindow::closeWithoutAsking);
}

void LeaveHooks::askBeforeLogout(lk::ui::MainWindow &window)
{
    QObject::connect(
        qGuiApp, &QGuiApplication::commitDataRequest, &window,
        [&window](QSessionManager &manager) {
            const bool mayAsk = manager.allowsInteraction();
            const bool leave = window.prepareLogout(mayAsk);
            if (mayAsk)
                manager.release();
            if (!leave)
                manager.cancel();
        },
        Qt::DirectConnection); // the manager is valid only during the call
}

void LeaveHooks::followDemo(lk::ui::MainWindow &window, DemoMotion &demo)
{
    lk::ui::LeaveGuard *guard = window.leaveGuard();
    guard->setDemoRunning(demo.isRunning());
    QObject::connect(&demo, &DemoMotion::started, guard, [guard] { guard->setDemoRunning(true); });
    QObject::connect(&demo, &DemoMotion::stopped, guard, [guard] { guard->setDemoRunning(false); });
}
