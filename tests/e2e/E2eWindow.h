#pragma once

// The real lkstudio window connected to lksim's pseudo-terminal, for the end-to-end tests
// that drive the GUI (e-stop, supervision).

#include <main/AppSettings.h>
#include <main/MainWindow.h>
#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>
#include <recording/BlackBoxRecorder.h>
#include <recording/RecordingController.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <memory>

namespace lk::e2e {

/// Where an end-to-end window's black box saves (an e-stop, a link loss): a temporary folder
/// of the test process, removed when it ends; never the user's recordings.
inline QString blackBoxFolder()
{
    static QTemporaryDir dir;
    return dir.filePath(QStringLiteral("recordings"));
}

/// Shows a window on `settings` (its black box saving into blackBoxFolder()), connects it to `port`
/// at 115200 baud (no auto-reconnect) and waits until the scan on connect has found `drives` and
/// polling runs. On failure the calling test has failed (QTest) and `window` may be partly set up.
inline void openWindowOnLksim(std::unique_ptr<ui::MainWindow> &window, ui::AppSettings *settings,
                              const QString &port, const QVector<int> &drives, int waitMs)
{
    window = std::make_unique<ui::MainWindow>(settings);
    window->recording()->blackBox()->setFolder(blackBoxFolder());
    window->resize(1400, 900);
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    ui::ConnectionChoice c;
    c.kind = ui::ConnectionChoice::Kind::Serial;
    c.port = port;
    c.baud = 115200;
    c.autoReconnect = false;
    window->connectTo(c, false);
    QTRY_COMPARE_WITH_TIMEOUT(window->busModel()->ids(), drives, waitMs);
    QTRY_VERIFY_WITH_TIMEOUT(window->busModel()->isPolling(), waitMs);
}

} // namespace lk::e2e
