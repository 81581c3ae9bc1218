// The drive views over a real serial port: lksim serves a simulated bus on a pseudo-terminal
// and the views talk to it through SerialTransport and BusSession, as lkstudio does with an
// adapter. Checks are made on what the drives answer and on lksim's frame log.
#include <LksimProcess.h>

#include <drive/ConfirmDialog.h>
#include <drive/ControlModePanel.h>
#include <drive/ControlView.h>
#include <drive/DriveInfoView.h>
#include <drive/EncoderView.h>
#include <drive/ParameterTable.h>
#include <drive/TuningSetV23.h>
#include <drive/TuningView.h>

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <transport/SerialTransport.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QSpinBox>

#include <cmath>
#include <memory>

using lk::protocol::Command;

namespace {

constexpr int kWaitMs = 30000;

/// One lksim process and a scanned session on its pty.
class PtyRig {
public:
    explicit PtyRig(const QString &romDir) : m_romDir(romDir), sim(QStringLiteral(LKSIM_PATH)) {}
    ~PtyRig() { session.close(); }

    bool start()
    {
        const QStringList args{QStringLiteral("--motors"),    QStringLiteral("1:MF,3:MS"),
                               QStringLiteral("--rom-dir"),   m_romDir,
                               QStringLiteral("--wire-time"), QStringLiteral("--verbose")};
        if (!sim.start(args))
            return false;
        lk::transport::SerialSettings settings;
        settings.portName = sim.devicePath();
        lk::bus::BusConfig config;
        config.minMarginMs = 100; // a loaded machine: late is not silent
        config.initialMarginMs = 100;
        config.maxMarginMs = 400;
        session.open(lk::transport::SerialTransport::factory(settings), 115200, config);
        if (!QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs))
            return false;
        QSignalSpy finished(&session, &lk::bus::BusSession::scanFinished);
        lk::bus::ScanOptions options;
        options.lastId = 4;
        session.scan(options);
        return finished.count() > 0 || finished.wait(kWaitMs);
    }

    /// One request, waited for (the test thread may wait; the views never do).
    std::optional<lk::protocol::Reply> ask(Command command, int id)
    {
        QSignalSpy done(&session, &lk::bus::BusSession::requestCompleted);
        const quint64 ticket = session.send(*lk::protocol::build::plain(command, id).request);
        std::optional<lk::protocol::Reply> reply;
        const bool completed = QTest::qWaitFor(
            [&] {
                for (const QList<QVariant> &args : std::as_const(done)) {
                    const auto r = args.at(0).value<lk::bus::RequestResult>();
                    if (r.ticket == ticket) {
                        reply = r.reply;
                        return true;
                    }
                }
                return false;
            },
            kWaitMs);
        return completed ? reply : std::nullopt;
    }

    /// Frames lksim received for `id` with `command` (from its --verbose log).
    int framesSeen(int id, Command command)
    {
        const QByteArray prefix = QStringLiteral("3E %1 %2")
                                      .arg(int(command), 2, 16, QLatin1Char('0'))
                                      .arg(id, 2, 16, QLatin1Char('0'))
                                      .toUpper()
                                      .toLatin1();
        int n = 0;
        for (const QByteArray &frame : sim.receivedFrames())
            n += frame.startsWith(prefix) ? 1 : 0;
        return n;
    }

    QString m_romDir;
    lk::e2e::LksimProcess sim;
    lk::bus::BusSession session;
};

template <typename View> void attach(View &view, PtyRig &rig, int id)
{
    view.setSession(&rig.session);
    view.setConnected(true);
    view.setDrive(id, rig.session.knownMotors().value(id));
    view.resize(1200, 760);
    view.show();
}

} // namespace

class tst_DriveViewsPty : public QObject {
    Q_OBJECT
private slots:
    void romWriteSurvivesLksimRestart();
    void controlAndRefusalOverPty();
    void zeroToolsAndReportOverPty();
};

void tst_DriveViewsPty::romWriteSurvivesLksimRestart()
{
    QTemporaryDir rom;
    lk::ui::ConfirmDialog::ScopedPolicy yes([](const lk::ui::ConfirmRequest &) { return true; });
    {
        PtyRig rig(rom.path());
        QVERIFY2(rig.start(), qPrintable(rig.sim.errorString()));
        lk::ui::TuningView view;
        attach(view, rig, 1);
        QTRY_VERIFY_WITH_TIMEOUT(view.readComplete() && !view.isBusy(), kWaitMs);
        view.table()->editor(lk::ui::TuningSetV23::SpeedKp)->setValue(77);
        view.writeToRam();
        QTRY_VERIFY_WITH_TIMEOUT(!view.isBusy() &&
                                     view.driveValues().value(lk::ui::TuningSetV23::SpeedKp) == 77,
                                 kWaitMs);
        QVERIFY(view.romWarningShown());
        view.table()->editor(lk::ui::TuningSetV23::AngleKp)->setValue(66);
        view.writeToRom();
        QTRY_VERIFY_WITH_TIMEOUT(!view.isBusy() &&
                                     view.driveValues().value(lk::ui::TuningSetV23::AngleKp) == 66,
                                 kWaitMs);
        QVERIFY(!view.romWarningShown());
        QCOMPARE(rig.framesSeen(1, Command::WritePidRom), 1);
    }
    // A new lksim on the same ROM directory: a power cycle of the drives.
    PtyRig rig(rom.path());
    QVERIFY2(rig.start(), qPrintable(rig.sim.errorString()));
    const auto reply = rig.ask(Command::ReadPid, 1);
    QVERIFY(reply);
    const auto pid = std::get<lk::protocol::PidGains>(reply->payload);
    QCOMPARE(int(pid.angleKp), 66);
    QCOMPARE(int(pid.speedKp), 77); // the ROM write carried the whole pending set
}

void tst_DriveViewsPty::controlAndRefusalOverPty()
{
    QTemporaryDir rom;
    PtyRig rig(rom.path());
    QVERIFY2(rig.start(), qPrintable(rig.sim.errorString()));
    lk::ui::ControlView view;
    attach(view, rig, 1);
    view.modePanel()->setMode(lk::ui::ControlMode::Speed);
    view.modePanel()->setSpeed(360);
    QVERIFY(view.sendCommand().sent);
    int speed = 0;
    const bool reached = QTest::qWaitFor(
        [&] {
            const auto r = rig.ask(Command::ReadState2, 1);
            speed = r ? std::get<lk::protocol::State2>(r->payload).speedDps : -1;
            return std::abs(speed - 360) < 20;
        },
        kWaitMs);
    QVERIFY2(reached, qPrintable(QStringLiteral("speed %1 dps").arg(speed)));
    view.modePanel()->setMode(lk::ui::ControlMode::Torque);
    view.modePanel()->setTorqueA(5); // over the MF default soft limit of 2.25 A
    QVERIFY(!view.sendCommand().sent);
    view.motorOff();
    QVERIFY(rig.ask(Command::ReadState1, 1)); // everything before it has been on the wire
    QCOMPARE(rig.framesSeen(1, Command::Torque), 0);
    QCOMPARE(rig.framesSeen(1, Command::MotorOff), 1);
}

void tst_DriveViewsPty::zeroToolsAndReportOverPty()
{
    QTemporaryDir rom;
    PtyRig rig(rom.path());
    QVERIFY2(rig.start(), qPrintable(rig.sim.errorString()));
    lk::ui::ConfirmDialog::ScopedPolicy yes([](const lk::ui::ConfirmRequest &) { return true; });
    lk::ui::EncoderView encoder;
    attach(encoder, rig, 3);
    QSignalSpy checked(&encoder, &lk::ui::EncoderView::angleCheckFinished);
    encoder.clearAngle();
    QTRY_COMPARE_WITH_TIMEOUT(checked.count(), 1, kWaitMs);
    QCOMPARE(encoder.lastAngleCheck()->outcome, lk::ui::AngleCheck::Outcome::Cleared);

    lk::ui::DriveInfoView info;
    attach(info, rig, 3);
    QSignalSpy ready(&info, &lk::ui::DriveInfoView::busReportReady);
    info.gatherBusReport();
    QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kWaitMs);
    const auto report = *info.lastReport();
    QCOMPARE(report.drives.size(), 2);
    QCOMPARE(report.drives.at(0).id, 1);
    QCOMPARE(report.drives.at(1).id, 3);
    for (const auto &d : report.drives) {
        QVERIFY(d.model && d.pid && d.accelDps2 && d.state1);
        QVERIFY(d.problems.isEmpty());
    }
}

QTEST_MAIN(tst_DriveViewsPty)
#include "tst_driveviewspty.moc"
