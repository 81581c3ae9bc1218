// The whole window when the link goes: an unplug of the simulated bus (disconnected, sending
// disabled, what may still move said), reconnecting when allowed, and a port that cannot open.

#include "MainWindowFixture.h"

#include <drive/ControlView.h>
#include <main/DriveViews.h>
#include <main/EmergencyStopControl.h>
#include <main/LinkLossWatch.h>
#include <main/MainWindow.h>
#include <panels/DashboardPanel.h>
#include <panels/EmergencyStopButton.h>
#include <panels/MessageBanner.h>
#include <panels/Readout.h>
#include <panels/StatusSummary.h>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>

using lk::protocol::Command;
using lk::ui::ConnectionChoice;
using namespace lk::uitest;

class tst_MainWindowLink : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init() { QVERIFY(openWindow()); }
    void cleanup() { closeWindow(); }
    void unplugShowsDisconnectedAndDisablesSending();
    void reconnectsWhenAllowed();
    void openFailureIsExplainedInABanner();
};

void tst_MainWindowLink::unplugShowsDisconnectedAndDisablesSending()
{
    QVERIFY(selectDrive2());
    auto *dash = m_window->dashboard();
    dash->refresh();
    const QString temperature = dash->readout(QStringLiteral("temperature"))->value();
    turnDrive2AndUnplug();
    if (QTest::currentTestFailed())
        return;
    QVERIFY(!model()->canSend());
    QTRY_VERIFY_WITH_TIMEOUT(
        !m_window->findChild<QPushButton *>(QStringLiteral("clearErrorsButton"))->isEnabled(),
        kWaitMs);
    QVERIFY(!m_window->findChild<QPushButton *>(QStringLiteral("scanButton"))->isEnabled());
    QVERIFY(m_window->statusSummary()->linkText().startsWith(QStringLiteral("Disconnected")));
    QCOMPARE(m_window->banner()->level(), lk::ui::MessageBanner::Level::Warning);
    QVERIFY(m_window->banner()->isVisible());
    // What may still be moving is said, per drive, and stays.
    const QString warning = m_window->banner()->entryText(lk::ui::LinkLossWatch::entryKey(2));
    QVERIFY2(warning.contains(QStringLiteral("Drive 2 may still be moving")) &&
                 warning.contains(QStringLiteral("speed 360 dps")) &&
                 warning.contains(QStringLiteral("input-timeout protection")),
             qPrintable(warning));
    QCOMPARE(m_window->linkLossWatch()->warnedIds(), QVector<int>{2});
    QCOMPARE(m_window->driveViews()->control()->statusText(),
             QStringLiteral("Disconnected: nothing can be sent."));
    // Esc while disconnected: nothing can be sent, and the report says so and names drive 2.
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("NOTHING could be sent")) &&
                 stopReport().contains(QStringLiteral("Drive 2 (speed 360 dps")) &&
                 !stopReport().contains(QStringLiteral("acknowledged")),
             qPrintable(stopReport()));
    QCOMPARE(m_window->banner()->entryLevel(lk::ui::EmergencyStopControl::entryKey()),
             lk::ui::MessageBanner::Level::Error);
    QVERIFY(m_window->banner()->hasEntry(lk::ui::LinkLossWatch::entryKey(2)));
    // Everything stays on screen, greyed once stale.
    QCOMPARE(model()->ids(), kSimIds);
    QCOMPARE(dash->readout(QStringLiteral("temperature"))->value(), temperature);
    QTRY_VERIFY_WITH_TIMEOUT(dash->readout(QStringLiteral("temperature"))->isStale(), kWaitMs);
    // Auto-reconnect is off in this test: it stays down.
    QTest::qWait(1500);
    QCOMPARE(model()->connection().state, lk::transport::Transport::State::Disconnected);
    QVERIFY(m_window->emergencyStopButton()->isEnabled()); // never disabled
}

void tst_MainWindowLink::reconnectsWhenAllowed()
{
    if (model()->connection().state != lk::transport::Transport::State::Disconnected) {
        QVERIFY(selectDrive2());
        turnDrive2AndUnplug();
        if (QTest::currentTestFailed())
            return;
    }
    auto *box = m_window->findChild<QCheckBox *>(QStringLiteral("autoReconnect"));
    QVERIFY(!box->isChecked());
    QTest::mouseClick(box, Qt::LeftButton);
    QVERIFY(box->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(model()->canSend(), kWaitMs);
    // The offline notice goes with the outage.
    QTRY_VERIFY_WITH_TIMEOUT(m_window->driveViews()->control()->statusText() !=
                                 QStringLiteral("Disconnected: nothing can be sent."),
                             kWaitMs);
    // Drive 2's warning stays until a state read shows it stopped: stop it, and it goes.
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("acknowledged by")), qPrintable(stopReport()));
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->banner()->hasEntry(lk::ui::LinkLossWatch::entryKey(2)),
                             kWaitMs);
    QVERIFY(m_window->linkLossWatch()->warnedIds().isEmpty());
    // Polling resumes by itself: values come back to life.
    QTRY_VERIFY_WITH_TIMEOUT(
        !m_window->dashboard()->readout(QStringLiteral("temperature"))->isStale(), kWaitMs);
    QVERIFY(m_window->findChild<QPushButton *>(QStringLiteral("clearErrorsButton"))->isEnabled());
    QCOMPARE(model()->ids(), kSimIds);
}

void tst_MainWindowLink::openFailureIsExplainedInABanner()
{
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Serial;
    c.port = m_dir->filePath("no-such-adapter");
    c.autoReconnect = false;
    m_window->connectTo(c);
    // The message line (reports of earlier tests may stay below it until dismissed).
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->banner()->text().isEmpty(), kWaitMs);
    QVERIFY(m_window->banner()->isVisible());
    QCOMPARE(m_window->banner()->level(), lk::ui::MessageBanner::Level::Error);
    QVERIFY2(m_window->banner()->text().contains(QStringLiteral("does not exist")),
             qPrintable(m_window->banner()->text()));
    QVERIFY(!model()->canSend());
    QVERIFY(!m_window->statusSummary()->isSimulatedBadgeShown());
    QVERIFY(model()->ids().isEmpty());
}

QTEST_MAIN(tst_MainWindowLink)
#include "tst_mainwindowlink.moc"
