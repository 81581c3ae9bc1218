#include <drive/EncoderResolutions.h>
#include <panels/BusModel.h>
#include <panels/DashboardPanel.h>
#include <panels/DriveTree.h>
#include <panels/Format.h>
#include <panels/ListenStatisticsPane.h>
#include <panels/OverviewModel.h>
#include <panels/Readout.h>
#include <panels/StatisticsView.h>
#include <text/CommandTitle.h>

#include <QtTest/QtTest>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableWidget>

using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::ui::BusModel;
using lk::ui::DashboardPanel;
namespace protocol = lk::protocol;

namespace {

lk::bus::FoundMotor found(int id, protocol::Series series, const QString &motor, int errors = 0)
{
    lk::bus::FoundMotor m;
    m.id = id;
    m.baud = 115200;
    m.model.driverName = QStringLiteral("DRV-") + protocol::seriesName(series);
    m.model.motorName = motor;
    m.model.firmwareRaw = 23;
    m.model.hardwareRaw = 10;
    m.series = series;
    protocol::State1 s1;
    s1.temperatureC = 35;
    s1.voltageRaw = 240;
    s1.errorState = quint8(errors);
    m.state1 = s1;
    return m;
}

TelemetrySample motion(int id, bool power)
{
    TelemetrySample s;
    s.id = id;
    s.fields = TelemetryField::Temperature | TelemetryField::Speed | TelemetryField::Encoder |
               TelemetryField::MultiTurn | TelemetryField::SingleTurn |
               (power ? TelemetryField::Power : TelemetryField::IqA);
    s.temperatureC = 41;
    s.iqA = 1.25;
    s.power = 300;
    s.speedDps = 3600;
    s.encoder = 8192;
    s.multiTurnDeg = 7200;
    s.singleTurnDeg = 1800;
    return s;
}

} // namespace

class tst_Dashboard : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c()); // numbers as the rows below write them
    }
    void showsValues_data();
    void showsValues();
    void greysStaleValues();
    void errorFlagsAndClearButton();
    void errorFlagsFollowTheGeneration();
    void v235BusCurrentAndMotorState();
    void statisticsClearedOnDisconnect();
    void selectionFollowsEveryView();
    void encoderResolutionFromData();
    void powerAlwaysHasItsUnit_data();
    void powerAlwaysHasItsUnit();
    void drivesAppearOnlyWhileListening_data();
    void drivesAppearOnlyWhileListening();
    void unknownSeriesShowsNoTorque();
    void statisticsOfTheOtherMaster();
};

void tst_Dashboard::showsValues_data()
{
    QTest::addColumn<int>("series");
    QTest::addColumn<QString>("motor");
    QTest::addColumn<QString>("torque");
    QTest::addColumn<QString>("speedRpm");
    QTest::addColumn<QString>("multiTurn");
    QTest::addColumn<QString>("phase");
    QTest::addColumn<QString>("angleCaption");
    // Numbers use the C locale under QTest.
    QTest::newRow("MF rotor") << int(protocol::Series::MF) << "MF4015"
                              << "1.25 A"
                              << "600.0 rpm"
                              << "7200.00 \u00b0"
                              << ""
                              << "rotor";
    QTest::newRow("MG geared") << int(protocol::Series::MG) << "MG5010E-i10"
                               << "1.25 A"
                               << "60.0 rpm"
                               << "720.00 \u00b0"
                               << ""
                               << "output shaft";
    QTest::newRow("MS power") << int(protocol::Series::MS) << "MS5005"
                              << "300 rel."
                              << "600.0 rpm"
                              << "7200.00 \u00b0"
                              << "not on MS"
                              << "rotor";
}

void tst_Dashboard::showsValues()
{
    QFETCH(int, series);
    QFETCH(QString, motor);
    QFETCH(QString, torque);
    QFETCH(QString, speedRpm);
    QFETCH(QString, multiTurn);
    QFETCH(QString, phase);
    QFETCH(QString, angleCaption);
    const auto s = protocol::Series(series);
    BusModel model;
    DashboardPanel dash(&model);
    dash.resize(1000, 700);
    dash.show();
    model.addFound(found(7, s, motor));
    model.applyTelemetry({motion(7, s == protocol::Series::MS)});
    dash.refresh();
    QCOMPARE(dash.readout(QStringLiteral("torque"))->value(), torque);
    QCOMPARE(dash.readout(QStringLiteral("speedRpm"))->value(), speedRpm);
    QCOMPARE(dash.readout(QStringLiteral("multiTurn"))->value(), multiTurn);
    QCOMPARE(dash.readout(QStringLiteral("voltage"))->value(), QStringLiteral("24.0 V"));
    QCOMPARE(dash.readout(QStringLiteral("temperature"))->value(), QStringLiteral("41 \u00b0C"));
    QVERIFY(!dash.readout(QStringLiteral("torque"))->isStale());
    if (!phase.isEmpty())
        QCOMPARE(dash.readout(QStringLiteral("phaseA"))->value(), phase);
    auto *note = dash.findChild<QLabel *>(QStringLiteral("angleNote"));
    QVERIFY(note->text().contains(angleCaption == QLatin1String("rotor") ? "rotor values"
                                                                         : "output shaft"));
}

void tst_Dashboard::greysStaleValues()
{
    BusModel model;
    DashboardPanel dash(&model);
    dash.show();
    model.addFound(found(1, protocol::Series::MF, QStringLiteral("MF4015")));
    model.applyTelemetry({motion(1, false)});
    dash.refresh();
    auto *speed = dash.readout(QStringLiteral("speedDps"));
    QVERIFY(!speed->isStale());
    // No update for over a second: greyed, value kept on screen.
    QTRY_VERIFY_WITH_TIMEOUT(speed->isStale(), 10000);
    QCOMPARE(speed->value(), QStringLiteral("3600 dps"));
    model.applyTelemetry({motion(1, false)});
    QTRY_VERIFY_WITH_TIMEOUT(!speed->isStale(), 5000);
}

void tst_Dashboard::errorFlagsAndClearButton()
{
    BusModel model;
    DashboardPanel dash(&model);
    dash.show();
    QSignalSpy clear(&dash, &DashboardPanel::clearErrorsRequested);
    model.addFound(found(3, protocol::Series::MF, QStringLiteral("MF4015"), 0x09));
    lk::bus::ConnectionStatus open;
    open.state = lk::transport::Transport::State::Open;
    open.canTransmit = true;
    model.setConnection(open, true);
    dash.refresh();
    auto *flags = dash.findChild<QLabel *>(QStringLiteral("errorFlags"));
    QVERIFY(flags->text().contains(QStringLiteral("Low voltage")));
    QVERIFY(flags->text().contains(QStringLiteral("Over-temperature")));
    auto *button = dash.findChild<QPushButton *>(QStringLiteral("clearErrorsButton"));
    QVERIFY(button->isEnabled());
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(clear.count(), 1);
    QCOMPARE(clear.at(0).at(0).toInt(), 3);
    lk::bus::ConnectionStatus gone;
    gone.state = lk::transport::Transport::State::Disconnected;
    model.setConnection(gone, true);
    dash.refresh();
    QVERIFY(!button->isEnabled()); // nothing that sends while the link is down
}

// V2.35 names all eight bits (docs/V2.35.md section 5): 0x50 is over-current and stall, where the
// V2.3 names would say nothing but "Error bit 4, Error bit 6".
void tst_Dashboard::errorFlagsFollowTheGeneration()
{
    BusModel model;
    DashboardPanel dash(&model);
    auto m = found(4, protocol::Series::MS, QStringLiteral("MS4015"), 0x50);
    m.model.generation = protocol::Generation::V2_35;
    m.model.firmwareRaw = 235;
    model.addFound(m);
    model.addFound(found(5, protocol::Series::MF, QStringLiteral("MF4015"), 0x50));
    model.setCurrentId(4);
    dash.refresh();
    auto *flags = dash.findChild<QLabel *>(QStringLiteral("errorFlags"));
    QVERIFY2(flags->text().contains(QStringLiteral("Over-current, Stall")),
             qPrintable(flags->text()));
    lk::ui::OverviewModel overview(&model);
    QCOMPARE(overview.data(overview.index(1, lk::ui::OverviewModel::Errors)).toString(),
             QStringLiteral("Error bit 4, Error bit 6"));
    // Without the model read, the generation is unknown: numbers, never a guessed name.
    QCOMPARE(lk::ui::Format::errorFlagsText(0x01, std::nullopt), QStringLiteral("Error bit 0"));
}

// Firmware 2.35 reports bus current and the motor state in 0x9A (docs/V2.35.md section 5); the
// dashboard shows them for such a drive, with the voltage at its 0.01 V resolution, and hides
// them for a V2.3 drive, whose reply has neither (never a made-up 0 A).
void tst_Dashboard::v235BusCurrentAndMotorState()
{
    BusModel model;
    DashboardPanel dash(&model);
    dash.resize(1000, 700);
    dash.show();
    auto m = found(3, protocol::Series::MS, QStringLiteral("MS4015"));
    m.model.generation = protocol::Generation::V2_35;
    m.model.firmwareRaw = 235;
    m.state1->generation = protocol::Generation::V2_35;
    m.state1->voltageRaw = 2400;
    m.state1->busCurrentRaw = 150;
    m.state1->motorStateRaw = 0x00;
    model.addFound(m);
    model.addFound(found(5, protocol::Series::MF, QStringLiteral("MF4015")));
    model.setCurrentId(3);
    dash.refresh();
    QCOMPARE(dash.readout(QStringLiteral("voltage"))->value(), QStringLiteral("24.00 V"));
    QVERIFY(dash.readout(QStringLiteral("busCurrent"))->isVisible());
    QCOMPARE(dash.readout(QStringLiteral("busCurrent"))->value(), QStringLiteral("1.50 A"));
    QCOMPARE(dash.readout(QStringLiteral("motorState"))->value(), QStringLiteral("on"));

    protocol::State1 off = *m.state1;
    off.motorStateRaw = 0x10;
    off.busCurrentRaw = -3;
    model.applyTelemetry({TelemetrySample::fromState1(3, off, 1.0)});
    dash.refresh();
    QCOMPARE(dash.readout(QStringLiteral("motorState"))->value(), QStringLiteral("off"));
    QCOMPARE(dash.readout(QStringLiteral("busCurrent"))->value(), QStringLiteral("-0.03 A"));

    model.setCurrentId(5);
    dash.refresh();
    QCOMPARE(dash.readout(QStringLiteral("voltage"))->value(), QStringLiteral("24.0 V"));
    QVERIFY(!dash.readout(QStringLiteral("busCurrent"))->isVisible());
    QVERIFY(!dash.readout(QStringLiteral("motorState"))->isVisible());
}

// The status bar, the dashboard and the statistics view read the model's figures: closing the
// link clears them, so no view shows the last link's rate as if it were current.
void tst_Dashboard::statisticsClearedOnDisconnect()
{
    BusModel model;
    lk::bus::BusStatistics st;
    st.bus.requests = 120;
    st.bus.transactionsPerSecond = 480;
    model.setStatistics(st);
    lk::bus::ConnectionStatus lost;
    lost.state = lk::transport::Transport::State::Disconnected;
    model.setConnection(lost, false);
    QCOMPARE(model.statistics().bus.requests, quint64(120)); // an unplug keeps the evidence
    QSignalSpy changed(&model, &BusModel::statisticsChanged);
    lk::bus::ConnectionStatus closed;
    closed.state = lk::transport::Transport::State::Closed;
    model.setConnection(closed, false);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(model.statistics().bus.requests, quint64(0));
    QCOMPARE(model.statistics().bus.transactionsPerSecond, 0.0);
}

void tst_Dashboard::selectionFollowsEveryView()
{
    BusModel model;
    lk::ui::DriveTree tree(&model);
    DashboardPanel dash(&model);
    tree.resize(800, 300);
    tree.show();
    dash.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tree));
    model.addFound(found(1, protocol::Series::MF, QStringLiteral("MF4015")));
    model.addFound(found(2, protocol::Series::MG, QStringLiteral("MG5010E-i10"), 0x01));
    QCOMPARE(model.currentId(), 1); // the first drive found is selected
    QTreeWidgetItem *item = tree.itemForId(2);
    QVERIFY(item);
    QTest::mouseClick(tree.viewport(), Qt::LeftButton, {}, tree.visualItemRect(item).center());
    QCOMPARE(model.currentId(), 2);
    dash.refresh();
    QVERIFY(dash.findChild<QLabel *>(QStringLiteral("driveIdentity"))
                ->text()
                .contains(QStringLiteral("Drive 2")));
    // Warnings you cannot miss: the row says it in words.
    QCOMPARE(item->text(lk::ui::DriveTree::ErrorsCol), QStringLiteral("Low voltage"));
    lk::ui::OverviewModel overview(&model);
    QCOMPARE(overview.rowCount(), 2);
    QCOMPARE(overview.data(overview.index(1, lk::ui::OverviewModel::Errors)).toString(),
             QStringLiteral("Low voltage"));
}

void tst_Dashboard::encoderResolutionFromData()
{
    BusModel model;
    DashboardPanel dash(&model);
    lk::ui::EncoderResolutions resolutions;
    dash.setEncoderResolutions(&resolutions);
    dash.show();
    // A V2.3 MS4015: its series default (12 bits) raised by data. (On V2.35 it starts at the
    // 16 bits docs/V2.35.md documents: tst_encoderview, tst_encoderresolution.)
    auto m = found(3, protocol::Series::MS, QStringLiteral("MS4015"));
    m.model.generation = protocol::Generation::V2_3;
    model.addFound(m);
    model.setCurrentId(3);
    // lkstudio hands every telemetry batch to the model and to the resolutions.
    auto feed = [&](int encoder) {
        TelemetrySample s = motion(3, true);
        s.encoder = encoder;
        model.applyTelemetry({s});
        resolutions.observe(lk::bus::TelemetryBatch{s});
        dash.refresh();
        return dash.readout(QStringLiteral("encoder"))->value();
    };
    QCOMPARE(feed(4000), QStringLiteral("4000 of 4096 (12-bit, series default)"));
    QCOMPARE(feed(43388), QStringLiteral("43388 of 65536 (16-bit, from data)"));
    // Never lowered by a smaller value afterwards.
    QCOMPARE(feed(6437), QStringLiteral("6437 of 65536 (16-bit, from data)"));
    // The user's choice wins, and both views read the same resolution.
    lk::bus::KnownMotor known;
    known.id = 3;
    known.series = protocol::Series::MS;
    known.model = m.model;
    known.generation = m.model.generation;
    resolutions.setUserBits(3, known, 18);
    QCOMPARE(feed(6437), QStringLiteral("6437 of 65536 (18-bit, your setting)"));
}

// An MS drive's power, 0 included, is shown with its unit wherever it is shown (the
// dashboard said "0" beside "0.00 A" for a current).
void tst_Dashboard::powerAlwaysHasItsUnit_data()
{
    QTest::addColumn<double>("power");
    QTest::addColumn<QString>("shown");
    QTest::newRow("0") << 0.0 << "0 rel.";
    QTest::newRow("300") << 300.0 << "300 rel.";
    QTest::newRow("-1000") << -1000.0 << "-1000 rel.";
}

void tst_Dashboard::powerAlwaysHasItsUnit()
{
    QFETCH(double, power);
    QFETCH(QString, shown);
    BusModel model;
    DashboardPanel dash(&model);
    dash.resize(1000, 700);
    dash.show();
    lk::ui::OverviewModel overview(&model);
    model.addFound(found(3, protocol::Series::MS, QStringLiteral("MS4015")));
    TelemetrySample s = motion(3, true);
    s.power = power;
    model.applyTelemetry({s});
    dash.refresh();
    QCOMPARE(dash.readout(QStringLiteral("torque"))->value(), shown);
    overview.refresh();
    QCOMPARE(overview.data(overview.index(0, lk::ui::OverviewModel::Torque)).toString(), shown);
    QCOMPARE(lk::ui::Format::power(power), shown);
}

void tst_Dashboard::drivesAppearOnlyWhileListening_data()
{
    QTest::addColumn<bool>("canTransmit");
    QTest::addColumn<bool>("appears");
    QTest::newRow("bus master: the scan says which drives") << true << false;
    QTest::newRow("listening: a drive that answers is there") << false << true;
}

void tst_Dashboard::drivesAppearOnlyWhileListening()
{
    QFETCH(bool, canTransmit);
    QFETCH(bool, appears);
    BusModel model;
    lk::bus::ConnectionStatus open;
    open.state = lk::transport::Transport::State::Open;
    open.baud = 1000000;
    open.canTransmit = canTransmit;
    open.mode = canTransmit ? lk::bus::LinkMode::Active : lk::bus::LinkMode::ListenOnly;
    model.setConnection(open, false);
    QCOMPARE(model.canSend(), canTransmit);
    QCOMPARE(model.isListening(), !canTransmit);
    model.applyTelemetry({motion(5, false)});
    lk::bus::KnownMotors known;
    known[9].id = 9;
    known[9].series = protocol::Series::MG;
    model.applyKnownMotors(known);
    QCOMPARE(model.ids(), appears ? (QVector<int>{5, 9}) : QVector<int>{});
    if (!appears)
        return;
    QCOMPARE(model.currentId(), 5);
    QCOMPARE(model.drive(5)->baud, 1000000);
    QVERIFY(model.drive(5)->has(TelemetryField::Temperature));
    QCOMPARE(model.drive(9)->series, std::optional(protocol::Series::MG));
}

void tst_Dashboard::unknownSeriesShowsNoTorque()
{
    BusModel model;
    DashboardPanel dash(&model);
    dash.show();
    lk::bus::ConnectionStatus open;
    open.state = lk::transport::Transport::State::Open;
    open.mode = lk::bus::LinkMode::ListenOnly;
    model.setConnection(open, false);
    // Decoded as MF by a bus that does not know the series: an MS drive's power as "iq".
    model.applyTelemetry({motion(5, false)});
    dash.refresh();
    auto *torque = dash.readout(QStringLiteral("torque"));
    QCOMPARE(torque->value(), QStringLiteral("\u2013"));
    QVERIFY(torque->toolTip().contains(QStringLiteral("Bus panel")));
    auto *button = dash.findChild<QPushButton *>(QStringLiteral("clearErrorsButton"));
    QVERIFY(!button->isEnabled());
    QVERIFY(button->toolTip().startsWith(QStringLiteral("Listen-only: this tool transmits")));
    lk::bus::KnownMotors known;
    known[5].id = 5;
    known[5].series = protocol::Series::MF; // the user chose it
    model.applyKnownMotors(known);
    dash.refresh();
    QCOMPARE(torque->value(), QStringLiteral("1.25 A"));
}

void tst_Dashboard::statisticsOfTheOtherMaster()
{
    BusModel model;
    lk::ui::StatisticsView view(&model);
    view.show();
    auto *pane = view.listenPane();
    QVERIFY(!pane->isVisible()); // bus master: its own figures
    lk::bus::ConnectionStatus open;
    open.state = lk::transport::Transport::State::Open;
    open.mode = lk::bus::LinkMode::ListenOnly;
    model.setConnection(open, false);
    QVERIFY(pane->isVisible());
    QVERIFY(view.title().contains(QStringLiteral("other master")));
    lk::bus::ListenStatistics st;
    st.requests = 1200;
    st.unanswered = 7;
    st.checksumErrors = 3;
    st.requestsPerSecond = 400;
    st.busLoad = 0.375;
    st.bytes = 20000;
    st.perDrive[5].requests = 600;
    st.perDrive[5].replies = 593;
    st.perDrive[5].unanswered = 7;
    st.perDrive[5].requestsPerSecond = 200;
    st.perDrive[5].latency = {593, 0.2, 0.4, 0.9, 1.5};
    st.perCommand[0x9C].requests = 1200;
    st.perCommand[0x9C].requestsPerSecond = 400;
    model.setListenStatistics(st);
    const QString summary = pane->summary();
    QVERIFY2(summary.contains(QStringLiteral("400 requests/s")), qPrintable(summary));
    QVERIFY2(summary.contains(QStringLiteral("bus load 37.5 %")), qPrintable(summary));
    QVERIFY2(summary.contains(QStringLiteral("7 unanswered")), qPrintable(summary));
    QVERIFY2(summary.contains(QStringLiteral("3 checksum errors")), qPrintable(summary));
    QTableWidget *drives = pane->drivesTable();
    QCOMPARE(drives->rowCount(), 1);
    QCOMPARE(drives->item(0, 0)->text(), QStringLiteral("5"));
    QCOMPARE(drives->item(0, 1)->text(), QStringLiteral("200.0"));
    QCOMPARE(drives->item(0, 3)->text(), QStringLiteral("7"));
    QCOMPARE(drives->item(0, 4)->text(), QStringLiteral("0.2 / 0.4 / 1.5 ms"));
    QTableWidget *commands = pane->commandsTable();
    QCOMPARE(commands->rowCount(), 1);
    QCOMPARE(commands->item(0, 0)->text(),
             lk::text::CommandTitle::withCode(protocol::Command::ReadState2));
    QCOMPARE(commands->item(0, 1)->text(), QStringLiteral("400.0"));
    QVERIFY2(!summary.contains(QStringLiteral("CAN error frames")), qPrintable(summary));
    // On CAN: the error frames and the frames of no drive the CAN listen path counts, instead
    // of checksums and garbage, which CAN frames do not have.
    st.canErrorFrames = 4;
    st.otherFrames = 9;
    model.setListenStatistics(st);
    model.setLink(protocol::Link::Can, QStringLiteral("can0"));
    const QString onCan = pane->summary();
    QVERIFY2(onCan.contains(QStringLiteral("4 CAN error frames")), qPrintable(onCan));
    QVERIFY2(onCan.contains(QStringLiteral("9 frames of no drive")), qPrintable(onCan));
    QVERIFY2(!onCan.contains(QStringLiteral("checksum")), qPrintable(onCan));
    lk::bus::ConnectionStatus closed;
    model.setConnection(closed, false);
    QVERIFY(!pane->isVisible());
    QCOMPARE(model.listenStatistics().requests, quint64(0)); // the next link starts afresh
}

QTEST_MAIN(tst_Dashboard)
#include "tst_dashboard.moc"
