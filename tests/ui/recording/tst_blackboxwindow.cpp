// The black box as lkstudio runs it: every connection records into the ring, the Traffic view
// shows the ring (so traffic from before the view was opened is there), "Hide polling" leaves
// the commands, and an emergency stop, a link loss or File -> Save write a recording whose
// path the banner names.
#include "../MainWindowFixture.h"

#include <panels/TrafficFilter.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>
#include <recording/RecordingReader.h>

#include <QtGui/QAction>
#include <QtWidgets/QCheckBox>

using namespace lk;
using lk::protocol::Command;

namespace {

/// The tx frames of `command` in a recording file.
int sentFrames(const QString &path, Command command)
{
    recording::RecordingReader reader;
    if (!reader.open(path))
        return -1;
    int n = 0;
    recording::RecordEvent e;
    while (reader.next(&e)) {
        if (e.kind == recording::RecordEvent::Kind::Tx && e.bytes.size() > 1 &&
            quint8(e.bytes.at(1)) == quint8(command))
            ++n;
    }
    return n;
}

int rowsOf(const ui::TrafficModel *m, Command command, bus::TrafficEvent::Kind kind)
{
    int n = 0;
    for (int row = 0; row < m->rowCount(); ++row)
        n += m->event(row).kind == kind && m->event(row).command == quint8(command) ? 1 : 0;
    return n;
}

} // namespace

class tst_BlackBoxWindow : public uitest::MainWindowFixture {
    Q_OBJECT
private slots:
    void init()
    {
        QVERIFY(openWindow()); // saves go to m_dir's recordings folder
    }
    void cleanup() { closeWindow(); }

    void trafficIsKeptWithTheViewClosed();
    void hidePollingLeavesTheCommands();
    void emergencyStopSavesAndTheBannerNamesThePath();
    void linkLossSaves();
    void saveOnRequestFromTheFileMenu();
    void anotherFactoryWrapperLeavesTheBlackBoxRecording();

private:
    ui::BlackBoxRecorder *blackBox() const { return m_window->recording()->blackBox(); }
    QString blackBoxEntry() const
    {
        return m_window->banner()->entryText(ui::RecordingController::entryKey());
    }
    /// Clear Errors to drive 2, acknowledged (a command among the polls), after some polling.
    void clearErrorsOn2()
    {
        QTRY_VERIFY_WITH_TIMEOUT(model()->statistics().bus.replies > 100, uitest::kWaitMs);
        const int before = sim()->requestCount(2, Command::ClearErrors);
        m_window->controller()->clearErrors(2);
        QTRY_COMPARE_WITH_TIMEOUT(sim()->requestCount(2, Command::ClearErrors), before + 1,
                                  uitest::kWaitMs);
    }
    /// The file the banner entry names.
    QString savedPath() const
    {
        for (const QString &word : blackBoxEntry().split(QLatin1Char(' ')))
            if (word.endsWith(QStringLiteral(".lkrec")))
                return word;
        return {};
    }
};

void tst_BlackBoxWindow::trafficIsKeptWithTheViewClosed()
{
    m_window->showView(QStringLiteral("dashboard"));
    QVERIFY(uitest::MainWindowFixture::selectDrive2());
    auto *traffic = m_window->traffic();
    QVERIFY(!traffic->wantsCapture());
    clearErrorsOn2();
    QCOMPARE(traffic->trafficModel()->rowCount(), 0); // nothing shown while closed ...

    m_window->showView(QStringLiteral("traffic"));
    const auto *m = traffic->trafficModel();
    // ... but the ring kept it: the command sent before the view opened, and its reply (the
    // reply's bytes may reach the ring a moment after the session took them: the view
    // follows the ring while open).
    QVERIFY(rowsOf(m, Command::ClearErrors, bus::TrafficEvent::Kind::Sent) >= 1);
    QTRY_VERIFY(rowsOf(m, Command::ClearErrors, bus::TrafficEvent::Kind::Frame) >= 1);
    QVERIFY(rowsOf(m, Command::ReadState2, bus::TrafficEvent::Kind::Frame) > 10);
    QCOMPARE(m->event(0).kind, bus::TrafficEvent::Kind::Note); // from the link's opening
    // Then it follows the ring while open.
    const int rows = m->rowCount();
    QTRY_VERIFY_WITH_TIMEOUT(m->rowCount() > rows + 20, uitest::kWaitMs);
}

void tst_BlackBoxWindow::hidePollingLeavesTheCommands()
{
    QVERIFY(uitest::MainWindowFixture::selectDrive2());
    clearErrorsOn2();
    m_window->showView(QStringLiteral("traffic"));
    auto *traffic = m_window->traffic();
    auto *hide = traffic->findChild<QCheckBox *>(QStringLiteral("trafficHidePolling"));
    QVERIFY(hide);
    const ui::TrafficFilter *filter = traffic->filter();
    const int all = filter->rowCount();
    hide->setChecked(true);
    QVERIFY(filter->rowCount() < all / 2);
    // Every row left is a command or a fault, never a poll.
    for (int row = 0; row < filter->rowCount(); ++row) {
        const int command = filter->index(row, 0).data(ui::TrafficModel::kCommandRole).toInt();
        const bool fault = filter->index(row, 0).data(ui::TrafficModel::kIsFaultRole).toBool();
        QVERIFY2(fault || !ui::TrafficFilter::isPolling(command), qPrintable(QString::number(row)));
    }
    // The request and its reply stay (the reply's bytes may reach the ring a moment after the
    // session took them, as in trafficIsKeptWithTheViewClosed: the view follows the ring).
    const auto clearErrorsRows = [filter] {
        int n = 0;
        for (int row = 0; row < filter->rowCount(); ++row)
            n += filter->index(row, 0).data(ui::TrafficModel::kCommandRole).toInt() ==
                         int(Command::ClearErrors)
                     ? 1
                     : 0;
        return n;
    };
    QTRY_VERIFY_WITH_TIMEOUT(clearErrorsRows() >= 2, uitest::kWaitMs);
    hide->setChecked(false);
    QVERIFY(filter->rowCount() >= all);
}

void tst_BlackBoxWindow::emergencyStopSavesAndTheBannerNamesThePath()
{
    QVERIFY(uitest::MainWindowFixture::findAllDrives());
    m_window->emergencyStop();
    QTRY_VERIFY_WITH_TIMEOUT(!savedPath().isEmpty(), uitest::kWaitMs);
    QVERIFY2(blackBoxEntry().contains(QStringLiteral("emergency stop")),
             qPrintable(blackBoxEntry()));
    const QString path = savedPath();
    QVERIFY2(path.startsWith(blackBox()->folder()), qPrintable(path));
    QVERIFY(path.contains(QStringLiteral("emergency-stop")));
    // The recording holds the stop itself: a Motor Off to every ID 1..32.
    QCOMPARE(sentFrames(path, Command::MotorOff), 32);
    QVERIFY(sentFrames(path, Command::ReadState2) > 0); // and the polling before it
}

void tst_BlackBoxWindow::linkLossSaves()
{
    QVERIFY(uitest::MainWindowFixture::findAllDrives());
    QVERIFY(sim()->requestDisconnect());
    QTRY_VERIFY_WITH_TIMEOUT(!savedPath().isEmpty(), uitest::kWaitMs);
    QVERIFY(savedPath().contains(QStringLiteral("link-lost")));
    QVERIFY(sentFrames(savedPath(), Command::ReadState2) > 0);
}

void tst_BlackBoxWindow::saveOnRequestFromTheFileMenu()
{
    QVERIFY(uitest::MainWindowFixture::findAllDrives());
    QAction *save = m_window->findChild<QAction *>(QStringLiteral("saveBlackBox"));
    QVERIFY(save);
    QVERIFY(save->text().contains(QStringLiteral("10 minute")));
    save->trigger();
    QVERIFY(!savedPath().isEmpty());
    QVERIFY(QFileInfo::exists(savedPath()));
    QVERIFY(sentFrames(savedPath(), Command::ReadState2) > 0);
}

void tst_BlackBoxWindow::anotherFactoryWrapperLeavesTheBlackBoxRecording()
{
    // One mechanism for every wrapper of the connection's transports: one added after the
    // black box's (as the tests' byte counters are) wraps it, and does not replace it.
    QStringList made;
    m_window->controller()->addFactoryWrapper(
        [&made](bus::TransportFactory inner, const ui::ConnectionChoice &choice) {
            made << (choice.isSimulator() ? QStringLiteral("simulator") : choice.port);
            return inner;
        });
    QVERIFY(connectToSimulator());
    QCOMPARE(made, QStringList{QStringLiteral("simulator")});
    QVERIFY(blackBox()->box());
    QTRY_VERIFY_WITH_TIMEOUT(blackBox()->box()->bytes() > 0, uitest::kWaitMs);
}

QTEST_MAIN(tst_BlackBoxWindow)
#include "tst_blackboxwindow.moc"
