#pragma once

// The whole window against the in-process simulated bus, for the tst_mainwindow* tests: each
// test function gets a window and settings of its own (openWindow() in init(), closeWindow()
// in cleanup()), so that every function runs alone and in any order.

#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/CommandedMotion.h>
#include <main/EmergencyStopControl.h>
#include <main/MainWindow.h>
#include <panels/BusModel.h>
#include <panels/MessageBanner.h>
#include <recording/BlackBoxRecorder.h>
#include <recording/RecordingController.h>

#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimDrive.h>
#include <transport/SimBusHandle.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <memory>

namespace lk::uitest {

constexpr int kWaitMs = 20000; // generous: a loaded 2-core CI machine
inline const QVector<int> kSimIds{1, 2, 3, 4};

inline ui::ConnectionChoice simulatorChoice()
{
    ui::ConnectionChoice c;
    c.kind = ui::ConnectionChoice::Kind::Simulator;
    c.autoReconnect = false;
    return c;
}

/// A fresh MainWindow on fresh settings, and the steps that bring its bus to where a test
/// starts. Test classes derive from it and call openWindow()/closeWindow() in init()/cleanup().
class MainWindowFixture : public QObject {
protected:
    /// A new temporary settings file and a new window, shown.
    bool openWindow()
    {
        m_dir = std::make_unique<QTemporaryDir>();
        if (!m_dir->isValid())
            return false;
        m_settings = std::make_unique<ui::AppSettings>(m_dir->filePath("lkstudio.ini"));
        m_window = std::make_unique<ui::MainWindow>(m_settings.get());
        // Black-box saves (an e-stop, a link loss) go to the test's folder, not the user's.
        m_window->recording()->blackBox()->setFolder(m_dir->filePath("recordings"));
        m_window->resize(1400, 900);
        m_window->show();
        return QTest::qWaitForWindowExposed(m_window.get());
    }
    void closeWindow()
    {
        m_window.reset();
        m_settings.reset();
        m_dir.reset();
    }

    ui::BusModel *model() const { return m_window->busModel(); }
    std::shared_ptr<transport::SimBusHandle> sim() const
    {
        return m_window->controller()->simulator();
    }
    QString stopReport() const
    {
        return m_window->banner()->entryText(ui::EmergencyStopControl::entryKey());
    }

    /// How many motor_off each simulated drive has received.
    QVector<int> motorOffCounts() const
    {
        QVector<int> counts;
        for (int id : kSimIds)
            counts << sim()->requestCount(id, protocol::Command::MotorOff);
        return counts;
    }

    /// Command every simulated drive to turn at 360 dps (as the Control view would).
    void spinAll()
    {
        for (int id : kSimIds)
            m_window->controller()->session()->send(*protocol::build::speed(id, 360).request);
        QTRY_VERIFY_WITH_TIMEOUT(inState(sim::SimDrive::RunState::Running) == kSimIds.size() &&
                                     m_window->commandedMotion()->movingIds() == kSimIds,
                                 kWaitMs);
    }

    int inState(sim::SimDrive::RunState state) const
    {
        int n = 0;
        sim()->withBus([&n, state](sim::SimBus &bus) {
            for (int id : kSimIds)
                n += bus.drive(id)->runState() == state ? 1 : 0;
        });
        return n;
    }

    bool allOff() const { return inState(sim::SimDrive::RunState::Off) == kSimIds.size(); }

    /// Connected to the simulated bus, auto-reconnect off.
    bool connectToSimulator()
    {
        if (model()->canSend() && model()->isSimulated())
            return true;
        m_window->connectTo(simulatorChoice());
        return QTest::qWaitFor([this] { return model()->canSend(); }, kWaitMs);
    }

    /// Connected, every simulated drive found and polled.
    bool findAllDrives()
    {
        // Scanning on connect is on by default: the scan finds the four drives, then polls them.
        return connectToSimulator() &&
               QTest::qWaitFor([this] { return model()->ids() == kSimIds && model()->isPolling(); },
                               kWaitMs);
    }

    /// Every drive found, drive 2 the current one.
    bool selectDrive2()
    {
        if (!findAllDrives())
            return false;
        if (model()->currentId() != 2)
            model()->setCurrentId(2);
        return true;
    }

    /// Drive 2 turning when the link drops.
    void turnDrive2AndUnplug()
    {
        m_window->controller()->session()->send(*protocol::build::speed(2, 360).request);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->commandedMotion()->movingIds(), QVector<int>{2},
                                  kWaitMs);
        QVERIFY(sim()->requestDisconnect());
        QTRY_COMPARE_WITH_TIMEOUT(model()->connection().state,
                                  lk::transport::Transport::State::Disconnected, kWaitMs);
    }

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<ui::AppSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

} // namespace lk::uitest
