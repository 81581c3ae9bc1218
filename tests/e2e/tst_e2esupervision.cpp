// Nothing the tool set moving runs on unwatched, end to end: the real lkstudio window on lksim
// over a pseudo-terminal (wire time at 115200 baud). A drive under torque past its soft speed
// limit is stopped by the bus thread's speed watch and ends at rest; quitting, disconnecting
// and a termination signal stop a turning drive (through the question's default, or without
// asking) or leave it turning at the user's explicit choice. Each drive's speed afterwards is
// read on the bus by a session of the test's own, after the window has let go of the port.
// Faults raised by lksim (--fault) are told per drive (banner entry, log line with the time
// and the flags), their values shown red, and the Control view states the trip.

#include "E2eUtil.h"
#include "E2eWindow.h"

#include <LeaveHooks.h>
#include <drive/ControlView.h>
#include <drive/DriveStateCheck.h>
#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/CommandedMotion.h>
#include <main/DriveFaultWatch.h>
#include <main/DriveViews.h>
#include <main/LeaveGuard.h>
#include <main/MainWindow.h>
#include <main/SpeedWatchReport.h>
#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>
#include <panels/DriveHealth.h>
#include <panels/MessageBanner.h>
#include <panels/OverviewModel.h>
#include <panels/OverviewPanel.h>
#include <panels/StatusColors.h>
#include <plot/PlotPanel.h>

#include <bus/BusSession.h>
#include <bus/SpeedWatch.h>
#include <protocol/RequestBuilder.h>
#include <system/SignalWatcher.h>
#include <transport/SerialTransport.h>

#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QPushButton>

#include <csignal>
#include <memory>

using namespace lk;
using protocol::Command;
using protocol::Series;

namespace {
constexpr int kWaitMs = 30000; // generous: the machine may be loaded
// The fault test's low voltage and over-temperature start this long after lksim: connecting
// takes well under a second here, so the test is listening and the torque command goes out
// first.
constexpr int kLowVoltageAtS = 4;
constexpr int kFaultAtS = 8;
const QVector<int> kDrives{1, 4};

QByteArray framePrefix(quint8 command, int id)
{
    return QByteArray("3E ") + QByteArray::number(command, 16).toUpper() + ' ' +
           QByteArray::number(id, 16).toUpper().rightJustified(2, '0');
}

/// Answers the leave question once it is shown: `button` is the object name of the button to
/// click ("cancel": the Cancel button), or empty for the default (Enter). The question's text
/// goes to `question`.
void answerLeaveQuestion(const QString &button, QString *question)
{
    auto *timer = new QTimer(qApp);
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, [timer, button, question] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box || box->objectName() != QStringLiteral("leaveGuardDialog"))
            return;
        timer->stop();
        timer->deleteLater();
        *question = box->text();
        if (button.isEmpty())
            QTest::keyClick(box, Qt::Key_Return);
        else if (button == QStringLiteral("cancel"))
            box->button(QMessageBox::Cancel)->click();
        else
            box->findChild<QPushButton *>(button)->click();
    });
    timer->start();
}
} // namespace

class tst_E2eSupervision : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void speedWatchStopsTorquePastTheLimit_data();
    void speedWatchStopsTorquePastTheLimit();
    void quitThroughTheDefaultStopsTheDrives();
    void leaveRunningKeepsTheDriveTurning();
    void cancelStays();
    void disconnectThroughTheDefaultStopsTheDrive();
    void terminationSignalStopsWithoutAsking();
    void faultsAreToldShownAndStopTheControlView();
    void v235MaxSpeedIsReadBeforeItIsSet();

private:
    /// The drive's speed read by a session of the test's own (the window has let go).
    std::optional<double> readSpeed(int id);
    /// The drive reads 0 dps within `ms` (it coasts down after its motor is off).
    bool comesToRest(int id, int ms = 5000);
    void spin(int id, double dps);
    ui::ControlView *control() const { return m_window->driveViews()->control(); }
    /// Whether lksim received `command` for drive `id`. Read only while nothing polls: lksim's
    /// log is read until it falls quiet.
    bool received(quint8 command, int id)
    {
        const QList<QByteArray> frames = m_sim->receivedFrames();
        return std::any_of(frames.cbegin(), frames.cend(), [command, id](const QByteArray &f) {
            return f.startsWith(framePrefix(command, id));
        });
    }

    QTemporaryDir m_dir;
    QElapsedTimer m_clock; ///< since lksim was started (its faults' clock)
    std::unique_ptr<e2e::LksimProcess> m_sim;
    std::unique_ptr<ui::AppSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void tst_E2eSupervision::init()
{
    QVERIFY(m_dir.isValid());
    m_sim = std::make_unique<e2e::LksimProcess>(QStringLiteral(LKSIM_PATH));
    QStringList args{"--motors", "1:MF,4:MH", "--wire-time", "--baud", "115200", "--verbose"};
    if (QTest::currentTestFunction() == QLatin1String("v235MaxSpeedIsReadBeforeItIsSet"))
        args[1] = QStringLiteral("1:MF4015@2.35,4:MH");
    if (QTest::currentTestFunction() == QLatin1String("faultsAreToldShownAndStopTheControlView"))
        args << "--fault"
             << QStringLiteral("1:over_temperature@%1,4:low_voltage@%2")
                    .arg(kFaultAtS)
                    .arg(kLowVoltageAtS);
    m_clock.start();
    QVERIFY2(m_sim->start(args), qPrintable(m_sim->errorString()));
    m_settings = std::make_unique<ui::AppSettings>(m_dir.filePath("lkstudio.ini"));
    // Scanning on connect finds the drives, then they are polled.
    e2e::openWindowOnLksim(m_window, m_settings.get(), m_sim->devicePath(), kDrives, kWaitMs);
}

void tst_E2eSupervision::cleanup()
{
    m_window.reset();
    m_settings.reset();
    m_sim.reset();
}

std::optional<double> tst_E2eSupervision::readSpeed(int id)
{
    bus::BusSession session;
    transport::SerialSettings s;
    s.portName = m_sim->devicePath();
    session.open(transport::SerialTransport::factory(s), 115200);
    if (!QTest::qWaitFor([&] { return session.connection().isOpen(); }, kWaitMs))
        return std::nullopt;
    std::optional<bus::RequestResult> result;
    session.send(*protocol::build::plain(Command::ReadState2, id).request, &session,
                 [&result](const bus::RequestResult &r) { result = r; });
    if (!QTest::qWaitFor([&] { return result.has_value(); }, kWaitMs) || !result->ok())
        return std::nullopt;
    return std::get<protocol::State2>(result->reply->payload).speedDps;
}

bool tst_E2eSupervision::comesToRest(int id, int ms)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        if (readSpeed(id) == 0.0)
            return true;
        QTest::qWait(100);
    }
    return false;
}

void tst_E2eSupervision::spin(int id, double dps)
{
    m_window->busModel()->setCurrentId(id);
    QTRY_COMPARE_WITH_TIMEOUT(control()->driveId(), id, kWaitMs);
    QVERIFY(control()->sendMotion(protocol::build::speed(id, dps)).sent);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->commandedMotion()->movingIds().contains(id), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(m_window->busModel()->drive(id)->latest.speedDps - dps) < 20,
                             kWaitMs);
}

void tst_E2eSupervision::speedWatchStopsTorquePastTheLimit_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<double>("amps");
    QTest::newRow("MF, 0.3 A") << 1 << 0.3;
    QTest::newRow("MH, 3.9 A") << 4 << 3.9;
}

void tst_E2eSupervision::speedWatchStopsTorquePastTheLimit()
{
    QFETCH(int, id);
    QFETCH(double, amps);
    m_window->busModel()->setCurrentId(id);
    QTRY_COMPARE_WITH_TIMEOUT(control()->driveId(), id, kWaitMs);
    safety::SoftLimits limits = control()->softLimits();
    limits.maxSpeedDps = 720; // "Speed at most 720 dps", applied as the user does
    limits.maxTorqueA = 4;
    control()->setSoftLimits(limits);
    QSignalSpy tripped(m_window->controller()->session(), &bus::BusSession::speedWatchTripped);
    const auto built = protocol::build::torque(
        id, amps, protocol::DecodeContext{*m_window->busModel()->drive(id)->series});
    QVERIFY(control()->sendMotion(built).sent);

    QTRY_COMPARE_WITH_TIMEOUT(tripped.size(), 1, kWaitMs);
    const auto trip = tripped.at(0).at(0).value<bus::SpeedWatchTrip>();
    QCOMPARE(trip.id, id);
    QCOMPARE(trip.limitDps, 720.0);
    QCOMPARE(trip.source, bus::SpeedWatchSource::SoftLimit);
    QVERIFY2(std::abs(trip.speedDps) > 756, qPrintable(QString::number(trip.speedDps)));
    QVERIFY(trip.stopAcknowledged());
    qInfo("drive %d at %.1f A: stopped after reading %.0f dps, %.1f ms from that reading", id, amps,
          trip.speedDps, trip.reactionMs());
    // The user is told where and why, the drive comes to rest, and Motor Stop was what
    // stopped it.
    const QString key = ui::SpeedWatchReport::entryKey(id);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->banner()->hasEntry(key), kWaitMs);
    QVERIFY2(m_window->banner()->entryText(key).contains(QStringLiteral("720 dps")),
             qPrintable(m_window->banner()->entryText(key)));
    QVERIFY2(control()->statusText().contains(QStringLiteral("speed watch")),
             qPrintable(control()->statusText()));
    QTRY_VERIFY_WITH_TIMEOUT(m_window->busModel()->drive(id)->latest.speedDps == 0, kWaitMs);
    QVERIFY(m_window->controller()->session()->knownMotors().contains(id));
    m_window->controller()->disconnectBus();
    QVERIFY(received(0x81, id));
    QVERIFY(!received(0x80, id));
    QVERIFY(comesToRest(id));
    e2e::verifyNoCollisions(*m_sim);
}

void tst_E2eSupervision::quitThroughTheDefaultStopsTheDrives()
{
    spin(1, 360);
    spin(4, -360);
    QString question;
    answerLeaveQuestion({}, &question);
    QVERIFY(m_window->close()); // the question, the stop and its wait run inside close()
    QVERIFY(!m_window->isVisible());
    QCOMPARE(question, QStringLiteral("Stop drives 1, 4 before quitting?"));
    QVERIFY2(m_window->leaveGuard()->lastReport().contains(
                 QStringLiteral("acknowledged by drives 1, 4")),
             qPrintable(m_window->leaveGuard()->lastReport()));
    for (int id : kDrives) {
        QVERIFY(received(0x80, id));
        QVERIFY2(comesToRest(id), qPrintable(QStringLiteral("drive %1 still turns").arg(id)));
    }
    e2e::verifyNoCollisions(*m_sim);
}

void tst_E2eSupervision::leaveRunningKeepsTheDriveTurning()
{
    spin(1, 360);
    QString question;
    answerLeaveQuestion(QStringLiteral("leaveRunning"), &question);
    QVERIFY(m_window->close());
    QCOMPARE(question, QStringLiteral("Stop drive 1 before quitting?"));
    QVERIFY2(m_window->leaveGuard()->lastReport().startsWith(QStringLiteral("Left running")),
             qPrintable(m_window->leaveGuard()->lastReport()));
    QVERIFY(!received(0x80, 1));
    const std::optional<double> speed = readSpeed(1);
    QVERIFY(speed);
    QVERIFY2(qAbs(*speed - 360) < 20, qPrintable(QString::number(*speed)));
    e2e::verifyNoCollisions(*m_sim);
}

void tst_E2eSupervision::cancelStays()
{
    spin(1, 360);
    QString question;
    answerLeaveQuestion(QStringLiteral("cancel"), &question);
    QVERIFY(!m_window->close());
    QCOMPARE(question, QStringLiteral("Stop drive 1 before quitting?"));
    QVERIFY(m_window->isVisible());
    QVERIFY(m_window->busModel()->canSend());
    QCOMPARE(m_window->commandedMotion()->movingIds(), QVector<int>{1});
    m_window->controller()->session()->stopPolling();
    QTest::qWait(300); // the last replies pass: lksim's log falls quiet
    QVERIFY(!received(0x80, 1));
}

void tst_E2eSupervision::disconnectThroughTheDefaultStopsTheDrive()
{
    spin(4, 360);
    QString question;
    answerLeaveQuestion({}, &question);
    auto *button = m_window->findChild<QPushButton *>(QStringLiteral("connectButton"));
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton); // "Disconnect" while connected
    QCOMPARE(question, QStringLiteral("Stop drive 4 before disconnecting?"));
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->busModel()->canSend(), kWaitMs);
    QVERIFY2(m_window->banner()->text().contains(QStringLiteral("acknowledged by drive 4")),
             qPrintable(m_window->banner()->text()));
    QVERIFY(comesToRest(4));
    e2e::verifyNoCollisions(*m_sim);
}

void tst_E2eSupervision::terminationSignalStopsWithoutAsking()
{
    spin(1, 360);
    system::SignalWatcher watcher;
    QVERIFY(watcher.isValid());
    LeaveHooks::closeOnTermination(*m_window, watcher);
    ::raise(SIGTERM);
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->isVisible(), kWaitMs);
    QVERIFY(QApplication::activeModalWidget() == nullptr); // nothing was asked
    QVERIFY2(
        m_window->leaveGuard()->lastReport().contains(QStringLiteral("acknowledged by drive 1")),
        qPrintable(m_window->leaveGuard()->lastReport()));
    QVERIFY(comesToRest(1));
    e2e::verifyNoCollisions(*m_sim);
}

void tst_E2eSupervision::faultsAreToldShownAndStopTheControlView()
{
    // Drive 4 (MH) reads low voltage kLowVoltageAtS after lksim started; drive 1 (MF) under a
    // small torque (held still by friction) overheats kFaultAtS after it and switches itself
    // off.
    QVERIFY2(m_clock.elapsed() < (kLowVoltageAtS - 1) * 1000, "connecting took too long");
    QVERIFY(!m_window->banner()->hasEntry(ui::DriveFaultWatch::entryKey(4)));
    const ui::DriveFaultWatch *watch = m_window->faultWatch();
    const QRegularExpression logLine(
        QStringLiteral("^\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3} drive 4: fault flags "
                       ".*\\(0x01\\)$"));
    QTest::ignoreMessage(QtWarningMsg, logLine); // the test fails unless it is logged
    const QString key4 = ui::DriveFaultWatch::entryKey(4);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->banner()->hasEntry(key4), kWaitMs);
    QVERIFY2(m_window->banner()->entryText(key4).contains(QStringLiteral("Drive 4")),
             qPrintable(m_window->banner()->entryText(key4)));
    const ui::DriveRecord *d4 = m_window->busModel()->drive(4);
    QTRY_VERIFY_WITH_TIMEOUT(ui::DriveHealth::of(*d4).voltageOut(), kWaitMs);
    auto *overview = m_window->overview()->findChild<ui::OverviewModel *>();
    QVERIFY(overview);
    overview->refresh();
    const int row4 = int(m_window->busModel()->ids().indexOf(4));
    const QBrush red(ui::StatusColors::text(ui::StatusColors::Role::Error));
    QCOMPARE(
        overview->index(row4, ui::OverviewModel::Voltage).data(Qt::ForegroundRole).value<QBrush>(),
        red);
    QVERIFY(!m_window->banner()->hasEntry(ui::DriveFaultWatch::entryKey(1)));

    m_window->busModel()->setCurrentId(1);
    QTRY_COMPARE_WITH_TIMEOUT(control()->driveId(), 1, kWaitMs);
    QVERIFY2(m_clock.elapsed() < (kFaultAtS - 2) * 1000, "connecting took too long for the test");
    QVERIFY(control()->sendMotion(protocol::build::torque(1, 0.05, {Series::MF})).sent);
    QTRY_VERIFY_WITH_TIMEOUT(
        control()->statusText().contains(QStringLiteral("Sent Torque current")), kWaitMs);
    const QString key1 = ui::DriveFaultWatch::entryKey(1);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->banner()->hasEntry(key1), kWaitMs);
    QVERIFY2(m_window->banner()->entryText(key1).contains(QStringLiteral("temperature"),
                                                          Qt::CaseInsensitive),
             qPrintable(m_window->banner()->entryText(key1)));
    QVERIFY2(m_clock.elapsed() >= kFaultAtS * 1000, "the fault was told before lksim raised it");
    // The Control view states the trip instead of the command last sent.
    QTRY_VERIFY_WITH_TIMEOUT(control()->statusText().contains(QStringLiteral("stopped by itself")),
                             kWaitMs);
    QVERIFY2(!control()->statusText().contains(QStringLiteral("Sent Torque current")),
             qPrintable(control()->statusText()));
    QVERIFY(watch->events(1).join(' ').contains(QStringLiteral("stopped by itself")));
    // Its temperature climbs past the warning threshold: shown red too.
    const ui::DriveRecord *d1 = m_window->busModel()->drive(1);
    QTRY_VERIFY_WITH_TIMEOUT(ui::DriveHealth::of(*d1).hot, kWaitMs);
    overview->refresh();
    const int row1 = int(m_window->busModel()->ids().indexOf(1));
    QCOMPARE(overview->index(row1, ui::OverviewModel::Temperature)
                 .data(Qt::ForegroundRole)
                 .value<QBrush>(),
             red);
    // Temperature and voltage can be plotted.
    const QVector<ui::TelemetryChannel> pickable = ui::PlotPanel::pickableChannels();
    QVERIFY(pickable.contains(ui::TelemetryChannel::Temperature));
    QVERIFY(pickable.contains(ui::TelemetryChannel::Voltage));
}

void tst_E2eSupervision::v235MaxSpeedIsReadBeforeItIsSet()
{
    // A V2.35 drive tripped by the watch: its entry offers to set the drive's own Max Speed
    // (ParamID 0x9A) from the soft limit. It is read (0x40) before it is written (0x42), read
    // back, and not written again once it is at the limit.
    m_window->busModel()->setCurrentId(1);
    QTRY_COMPARE_WITH_TIMEOUT(control()->driveId(), 1, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(
        m_window->busModel()->drive(1)->generation() == protocol::Generation::V2_35, kWaitMs);
    // A V2.35 drive's motor state is read before motion (it powers up on).
    QTRY_VERIFY_WITH_TIMEOUT(control()->driveState()->motorOn() == std::optional<bool>(true),
                             kWaitMs);
    safety::SoftLimits limits = control()->softLimits();
    limits.maxSpeedDps = 720;
    control()->setSoftLimits(limits);
    QSignalSpy tripped(m_window->controller()->session(), &bus::BusSession::speedWatchTripped);
    const protocol::DecodeContext v235{Series::MF, protocol::Generation::V2_35};
    // Sent once the motor state has been read again (pending until then).
    const ui::MotionOutcome sent = control()->sendMotion(protocol::build::torque(1, 0.3, v235));
    QVERIFY2(sent.sent || sent.pending, qPrintable(control()->statusText()));
    QTRY_COMPARE_WITH_TIMEOUT(tripped.size(), 1, kWaitMs);
    // Its supply (24 V) was never out of range: the scan's probe, decoded before the model
    // was read, is not judged.
    QVERIFY2(!m_window->banner()->hasEntry(ui::DriveFaultWatch::entryKey(1)),
             qPrintable(m_window->banner()->entryText(ui::DriveFaultWatch::entryKey(1))));
    const QString key = ui::SpeedWatchReport::entryKey(1);
    QTRY_VERIFY_WITH_TIMEOUT(
        m_window->banner()->entryText(key).contains(ui::SpeedWatchReport::maxSpeedLink()), kWaitMs);
    // lksim's log is read once it falls quiet: nothing polls from here on. The Max Speed
    // frames (0x40/0x42 of ParamID 0x9A) after the torque, as "40" or "42" in order.
    m_window->controller()->session()->stopPolling();
    const auto maxSpeedFrames = [this] {
        QTest::qWait(300); // the last replies pass
        QStringList out;
        bool afterTorque = false;
        for (const QByteArray &f : m_sim->receivedFrames()) {
            const QList<QByteArray> b = f.split(' ');
            afterTorque = afterTorque || (b.value(1) == "A1" && b.value(2) == "01");
            if (afterTorque && (b.value(1) == "40" || b.value(1) == "42") && b.value(5) == "9A")
                out << QString::fromLatin1(b.value(1));
        }
        return out;
    };
    QCOMPARE(maxSpeedFrames(), QStringList{});
    emit m_window->banner()->entryLinkActivated(key, ui::SpeedWatchReport::maxSpeedLink());
    QTRY_VERIFY_WITH_TIMEOUT(
        m_window->banner()->entryText(key).contains(QStringLiteral("reads back 720.00 dps")),
        kWaitMs);
    // Read, written once, read back: in that order on the wire.
    QCOMPARE(maxSpeedFrames(), (QStringList{"40", "42", "40"}));
    // At the limit now: read again, nothing written.
    emit m_window->banner()->entryLinkActivated(key, ui::SpeedWatchReport::maxSpeedLink());
    QTRY_VERIFY_WITH_TIMEOUT(m_window->banner()->entryText(key).contains(
                                 QStringLiteral("not above your limit: nothing was written")),
                             kWaitMs);
    QCOMPARE(maxSpeedFrames(), (QStringList{"40", "42", "40", "40"}));
    e2e::verifyNoCollisions(*m_sim);
}

QTEST_MAIN(tst_E2eSupervision)
#include "tst_e2esupervision.moc"
