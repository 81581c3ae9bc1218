// The whole window on CAN: the built-in simulator on CAN, chosen as the connection bar does
// (sim::SimCanFront behind the black box's recorder) with one old CAN MG (ID 1, replies on 0x141)
// and one V2.36 MF (ID 2, replies on 0x182). Scan, dashboard, plots, the traffic view in candump
// notation, the emergency stop to every ID, and the views' rows on each generation.

#include "MainWindowFixture.h"

#include <drive/BrakePanel.h>
#include <drive/ConfirmDialog.h>
#include <drive/ControlView.h>
#include <drive/EncoderView.h>
#include <main/DriveViews.h>
#include <panels/DashboardPanel.h>
#include <panels/DriveRecord.h>
#include <panels/Readout.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>
#include <plot/PlotPanel.h>
#include <plot/TelemetryStore.h>
#include <sim/SimBusSpec.h>

#include <QtTest/QtTest>
#include <QtWidgets/QAbstractButton>

using namespace lk::uitest;
using lk::protocol::Command;
using lk::protocol::Generation;
using lk::protocol::Series;

namespace {
const QVector<int> kCanIds{1, 2};
} // namespace

class tst_MainWindowCanViews : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void scanFindsOneDriveOfEachGeneration();
    void dashboardShowsEachGenerationsValues_data();
    void dashboardShowsEachGenerationsValues();
    void dashboardShowsV236BusCurrentAndMotorState();
    void plotsReceiveSamplesOfBothDrives();
    void trafficRowsAreInCandumpNotation();
    void emergencyStopReachesEveryIdAsMotorOff();
    void encoderZeroInRamIsSetAngleOnV236Only();
    void brakeOnV236ReadsItsState();
    void brakeOnOldCanIsAbsentAndSendsNothing();
    void tuningViewReadsOldCanGains();

private:
    bool findCanDrives();
    /// Drives found, their identity told as a user does on CAN (no model read), `id` current.
    bool selectIdentified(int id);
    /// The traffic view's raw column of every row so far, one string.
    QString trafficText();
    /// Traffic captured with "Keep recording", the view hidden: thousands of rows a second
    /// on CAN are not painted meanwhile.
    void captureTraffic();
    lk::ui::DriveRecord record(int id) const { return *model()->drive(id); }

    QString m_traffic;      ///< the raw column of every traffic row read so far
    quint64 m_rowsRead = 0; ///< rows ever added when m_traffic was last extended
};

void tst_MainWindowCanViews::init()
{
    m_traffic.clear();
    m_rowsRead = 0;
    QVERIFY(openWindow());
    m_window->controller()->setSimulatorSpec(
        *lk::sim::SimBusSpec::parse(QStringLiteral("1:MG,2:MF@2.35")));
}

void tst_MainWindowCanViews::cleanup()
{
    closeWindow();
}

bool tst_MainWindowCanViews::findCanDrives()
{
    // The built-in simulator on CAN, as the connection bar chooses it.
    lk::ui::ConnectionChoice choice = simulatorChoice();
    choice.simulatedCan = true;
    choice.bitRate = 1000000;
    m_window->connectTo(choice);
    if (!QTest::qWaitFor([this] { return model()->canSend(); }, kWaitMs))
        return false;
    return QTest::qWaitFor([this] { return model()->ids() == kCanIds && model()->isPolling(); },
                           kWaitMs);
}

bool tst_MainWindowCanViews::selectIdentified(int id)
{
    if (!findCanDrives())
        return false;
    auto *session = m_window->controller()->session();
    session->setDriveIdentity({1, Series::MG, Generation::V2_3, std::nullopt});
    session->setDriveIdentity({2, Series::MF, Generation::V2_35, std::nullopt});
    model()->setCurrentId(id);
    return true;
}

QString tst_MainWindowCanViews::trafficText()
{
    // The rows since the last call (the view's ring drops its oldest: count from the end).
    auto *traffic = m_window->traffic();
    traffic->flush();
    const lk::ui::TrafficModel *m = traffic->trafficModel();
    const quint64 total = m->droppedRows() + quint64(m->rowCount());
    const int fresh = int(std::min<quint64>(total - m_rowsRead, quint64(m->rowCount())));
    for (int row = m->rowCount() - fresh; row < m->rowCount(); ++row)
        m_traffic += m->rawText(row) + QLatin1Char('\n');
    m_rowsRead = total;
    return m_traffic;
}

void tst_MainWindowCanViews::captureTraffic()
{
    m_window->showView(QStringLiteral("traffic"));
    auto *keep = m_window->traffic()->findChild<QAbstractButton *>(QStringLiteral("trafficRecord"));
    QVERIFY(keep);
    if (!keep->isChecked())
        keep->click();
    m_window->showView(QStringLiteral("dashboard"));
    QVERIFY(m_window->traffic()->wantsCapture());
}

void tst_MainWindowCanViews::scanFindsOneDriveOfEachGeneration()
{
    QVERIFY(findCanDrives());
    QVERIFY(m_window->controller()->session() != nullptr);
    // CAN has no model read: nothing asked 0x12.
    QCOMPARE(sim()->requestCount(1, Command::ReadModel), 0);
    QCOMPARE(sim()->requestCount(2, Command::ReadModel), 0);
    QVERIFY(!record(1).model || record(1).model->motorName.isEmpty());
}

void tst_MainWindowCanViews::dashboardShowsEachGenerationsValues_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<QString>("voltage");
    // Old CAN: 0.1 V in B3-B4 (MG at 48 V); V2.36: 0.01 V in B2-B3 (MF at 24 V). Read in the
    // other layout either would be ten times off or garbage.
    QTest::newRow("old CAN MG") << 1 << QStringLiteral("48.0 V");
    QTest::newRow("V2.36 MF") << 2 << QStringLiteral("24.00 V"); // 0.01 V on V2.36
}

void tst_MainWindowCanViews::dashboardShowsEachGenerationsValues()
{
    QFETCH(int, id);
    QFETCH(QString, voltage);
    QVERIFY(findCanDrives());
    model()->setCurrentId(id);
    m_window->showView(QStringLiteral("dashboard"));
    auto *dash = m_window->dashboard();
    QTRY_COMPARE_WITH_TIMEOUT(dash->readout(QStringLiteral("voltage"))->value(), voltage, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!dash->readout(QStringLiteral("encoder"))->value().isEmpty(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!dash->readout(QStringLiteral("multiTurn"))->value().isEmpty(),
                             kWaitMs);
}

void tst_MainWindowCanViews::dashboardShowsV236BusCurrentAndMotorState()
{
    // The V2.36 0x9A carries bus current and motor state (CAN.md 4): shown for drive 2, whose
    // generation came from its replies (no model read on CAN).
    QVERIFY(findCanDrives());
    model()->setCurrentId(2);
    m_window->showView(QStringLiteral("dashboard"));
    auto *dash = m_window->dashboard();
    QTRY_COMPARE_WITH_TIMEOUT(dash->readout(QStringLiteral("voltage"))->value(),
                              QStringLiteral("24.00 V"), kWaitMs);
    QVERIFY(dash->readout(QStringLiteral("busCurrent"))->isVisibleTo(dash));
    QTRY_COMPARE_WITH_TIMEOUT(dash->readout(QStringLiteral("motorState"))->value(),
                              QStringLiteral("on"), kWaitMs);
}

void tst_MainWindowCanViews::plotsReceiveSamplesOfBothDrives()
{
    QVERIFY(findCanDrives());
    m_window->showView(QStringLiteral("plots"));
    auto *store = m_window->telemetryStore();
    for (int id : kCanIds) {
        QTRY_VERIFY_WITH_TIMEOUT(store->count(id, lk::ui::TelemetryChannel::Speed) > 10, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(store->count(id, lk::ui::TelemetryChannel::Voltage) > 2, kWaitMs);
    }
    QTRY_VERIFY_WITH_TIMEOUT(m_window->plots()->redrawCount() > 0, kWaitMs);
}

void tst_MainWindowCanViews::trafficRowsAreInCandumpNotation()
{
    QVERIFY(findCanDrives());
    captureTraffic();
    QTRY_VERIFY_WITH_TIMEOUT(m_window->traffic()->trafficModel()->rowCount() > 20, kWaitMs);
    QTRY_VERIFY2_WITH_TIMEOUT(trafficText().contains(QStringLiteral("141#9C00000000000000")),
                              qPrintable(trafficText().left(300)), kWaitMs);
    // The V2.36 drive's replies on 0x182, with their data.
    QTRY_VERIFY_WITH_TIMEOUT(trafficText().contains(QStringLiteral("182#9C")), kWaitMs);
    QVERIFY2(!trafficText().contains(QStringLiteral("3E ")), qPrintable(trafficText().left(400)));
}

void tst_MainWindowCanViews::emergencyStopReachesEveryIdAsMotorOff()
{
    QVERIFY(findCanDrives());
    captureTraffic();
    for (int id : kCanIds)
        m_window->controller()->session()->send(*lk::protocol::build::speed(id, 0).request);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_VERIFY2_WITH_TIMEOUT(
        stopReport().contains(QStringLiteral("acknowledged by drive(s) 1, 2")),
        qPrintable(stopReport()), kWaitMs);
    // Motor Off went to every ID 1..32, each on its own request ID, in candump notation.
    for (int id = 1; id <= 32; ++id) {
        const QString frame =
            QStringLiteral("%1#8000000000000000").arg(0x140 + id, 3, 16).toUpper();
        QTRY_VERIFY2_WITH_TIMEOUT(trafficText().contains(frame), qPrintable(frame), kWaitMs);
    }
    for (int id : kCanIds)
        QVERIFY(sim()->requestCount(id, Command::MotorOff) >= 1);
}

void tst_MainWindowCanViews::encoderZeroInRamIsSetAngleOnV236Only()
{
    // V2.36 0x95 sets the position (B4..B7, here 0); the old generation's 0x95 is "not
    // implemented" (CAN.md 7), so the Encoder view sends it nowhere there.
    QVERIFY(selectIdentified(1));
    auto *encoder = m_window->driveViews()->encoder();
    // The user says yes to the question before each zero.
    lk::ui::ConfirmDialog::ScopedPolicy yes([](const lk::ui::ConfirmRequest &) { return true; });
    encoder->clearAngle(); // drive 1, old CAN: refused
    model()->setCurrentId(2);
    encoder->clearAngle(); // drive 2, V2.36: sent
    QTRY_COMPARE_WITH_TIMEOUT(sim()->requestCount(2, Command::ClearAngle), 1, kWaitMs);
    QCOMPARE(sim()->requestCount(1, Command::ClearAngle), 0);
}

void tst_MainWindowCanViews::brakeOnV236ReadsItsState()
{
    // CAN has no model read: the generation the user chose (or the replies told) is what
    // offers 0x8C, and it reaches the panel although the drive's settings key stays "id2".
    QVERIFY(selectIdentified(2));
    auto *brake = m_window->driveViews()->control()->brakePanel();
    QSignalSpy read(brake, &lk::ui::BrakePanel::stateRead);
    QTRY_VERIFY2_WITH_TIMEOUT(brake->absence().isEmpty(), qPrintable(brake->absence()), kWaitMs);
    auto *readButton = brake->findChild<QAbstractButton *>(QStringLiteral("brakeRead"));
    QVERIFY(readButton);
    QTRY_VERIFY_WITH_TIMEOUT(readButton->isEnabled(), kWaitMs);
    // A read already in flight (the one on selection) takes this one's place: ask until an
    // answer comes.
    QTRY_VERIFY2_WITH_TIMEOUT((brake->readState(), read.count() >= 1),
                              qPrintable(brake->statusText()), kWaitMs);
    QVERIFY(sim()->requestCount(2, Command::Brake) >= 1);
}

void tst_MainWindowCanViews::brakeOnOldCanIsAbsentAndSendsNothing()
{
    // The old CAN generation has no 0x8C: the panel names the dialect and sends nothing.
    QVERIFY(selectIdentified(1));
    auto *brake = m_window->driveViews()->control()->brakePanel();
    QTRY_VERIFY2_WITH_TIMEOUT(brake->absence().contains(QStringLiteral("CAN (old)")),
                              qPrintable(brake->absence()), kWaitMs);
    brake->readState();
    QTest::qWait(200);
    QCOMPARE(sim()->requestCount(1, Command::Brake), 0);
}

void tst_MainWindowCanViews::tuningViewReadsOldCanGains()
{
    // Old CAN keeps 0x30..0x34 (RAM and ROM): the Tuning view reads the gains of drive 1.
    QVERIFY(selectIdentified(1));
    m_window->showView(QStringLiteral("tuning"));
    QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(1, Command::ReadPid) >= 1, kWaitMs);
}

QTEST_MAIN(tst_MainWindowCanViews)
#include "tst_mainwindowcanviews.moc"
