#include "../support/FdAccessMode.h"
#include "E2eUtil.h"

#include <protocol/Frame.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtTest/QtTest>

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

// lkctl listen on a pseudo-terminal the test drives as "another master and its drive": the
// test writes both directions into the pty, as a tap on the bus sees them. lkctl holds the port
// read-only, writes nothing to it, prints the drive's replies and the master's commanded values
// in monitor's long layout (JSON lines, CSV), and says what the master did on standard error.

using lk::e2e::CtlResult;
using namespace lk;

namespace {

/// A pty whose master side is the bus; its slave is the port lkctl opens.
struct Bus {
    int master = -1;
    QString port;
    Bus()
    {
        int slave = -1;
        char name[256] = {};
        if (::openpty(&master, &slave, name, nullptr, nullptr) != 0)
            return;
        ::close(slave);
        termios t{};
        ::tcgetattr(master, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(master, TCSANOW, &t);
        ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
        port = QString::fromLocal8Bit(name);
    }
    ~Bus()
    {
        if (master >= 0)
            ::close(master);
    }
    void say(const QByteArray &bytes) const
    {
        QCOMPARE(::write(master, bytes.constData(), size_t(bytes.size())), ssize_t(bytes.size()));
    }
    /// Everything anyone wrote into the port since the last call.
    QByteArray heard() const
    {
        QByteArray all;
        char buf[512];
        ssize_t n;
        while ((n = ::read(master, buf, sizeof buf)) > 0)
            all.append(buf, int(n));
        return all;
    }
};

QByteArray state2Reply(protocol::Command command, int id, qint16 speedDps, quint16 encoder)
{
    protocol::Reply r;
    r.command = command;
    r.id = quint8(id);
    r.payload = protocol::State2{25, 3, false, speedDps, encoder, protocol::kIqReplyAmpsPerLsb};
    return r.encode();
}

/// A speed command of 120 dps to drive 3 and its reply, then a read_state2 to drive 7 that
/// nobody answers, then a read_state2 of drive 3 and its reply.
QByteArray machineTraffic()
{
    protocol::Request speed;
    speed.command = protocol::Command::Speed;
    speed.id = 3;
    speed.payload = protocol::SpeedCommand{12000};
    QByteArray bytes = speed.encode() + state2Reply(protocol::Command::Speed, 3, 118, 2390);
    bytes += protocol::encodeFrame(0x9C, 7, {});
    bytes += protocol::encodeFrame(0x9C, 3, {}) +
             state2Reply(protocol::Command::ReadState2, 3, 119, 2400);
    return bytes;
}

/// Runs `lkctl listen` on the bus while the test speaks `traffic` into it.
CtlResult listen(Bus &bus, const QStringList &extra, const QByteArray &traffic, int *accessMode)
{
    QProcess p;
    p.start(QStringLiteral(LKCTL_PATH),
            QStringList{QStringLiteral("listen"), QStringLiteral("--port"), bus.port,
                        QStringLiteral("--baud"), QStringLiteral("115200"),
                        QStringLiteral("--duration"), QStringLiteral("3")} +
                extra);
    CtlResult r;
    if (!p.waitForStarted(10000))
        return r;
    QElapsedTimer clock;
    clock.start();
    while ((*accessMode = testsupport::accessModeOf(p.processId(), bus.port)) < 0 &&
           clock.elapsed() < 10000)
        QTest::qWait(20);
    QTest::qWait(300); // the port is set up and its input flushed right after the open
    bus.say(traffic);
    p.waitForFinished(60000);
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    return r;
}

} // namespace

class tst_LkctlListen : public QObject {
    Q_OBJECT
private slots:
    void decodesAnotherMasterAndSendsNothing();
    void csvIsMonitorsLongLayout();
    void drivesTellTheLayouts();
    void argumentErrors_data();
    void argumentErrors();
};

void tst_LkctlListen::decodesAnotherMasterAndSendsNothing()
{
    Bus bus;
    QVERIFY(!bus.port.isEmpty());
    int mode = -1;
    const CtlResult r = listen(bus, {QStringLiteral("--json")}, machineTraffic(), &mode);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(mode, O_RDONLY);            // the port was held read-only
    QCOMPARE(bus.heard(), QByteArray()); // and not one byte came out of it
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 3);
    const QJsonObject commanded = QJsonDocument::fromJson(lines.at(0)).object();
    QCOMPARE(commanded.value(QStringLiteral("id")).toInt(), 3);
    QCOMPARE(commanded.value(QStringLiteral("commanded_speed_dps")).toDouble(), 120.0);
    QCOMPARE(commanded.size(), 3); // time_s, id and the commanded speed: nothing shown as 0
    const QJsonObject actual = QJsonDocument::fromJson(lines.at(1)).object();
    QCOMPARE(actual.value(QStringLiteral("speed_dps")).toDouble(), 118.0);
    QCOMPARE(actual.value(QStringLiteral("encoder")).toInt(), 2390);
    QVERIFY(!actual.contains(QStringLiteral("commanded_speed_dps")));
    const QJsonObject polled = QJsonDocument::fromJson(lines.at(2)).object();
    QCOMPARE(polled.value(QStringLiteral("speed_dps")).toDouble(), 119.0);
    QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
    QVERIFY2(r.err.contains("requests 3 "), r.err.constData());
    QVERIFY2(r.err.contains("paired 2, unanswered 1"), r.err.constData());
    QVERIFY2(r.err.contains("drive 7: requests 1 (") && r.err.contains("unanswered 1"),
             r.err.constData());
}

void tst_LkctlListen::csvIsMonitorsLongLayout()
{
    Bus bus;
    QVERIFY(!bus.port.isEmpty());
    int mode = -1;
    const CtlResult r = listen(bus, {}, machineTraffic(), &mode);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 4);
    QVERIFY2(lines.at(0).startsWith("time_s,id,temperature_c,"), lines.at(0).constData());
    QVERIFY2(lines.at(0).endsWith(
                 ",commanded_iq_a,commanded_power,commanded_speed_dps,commanded_angle_deg,"
                 "commanded_single_turn_deg,commanded_direction,commanded_increment_deg,"
                 "commanded_max_speed_dps"),
             lines.at(0).constData());
    const QList<QByteArray> header = lines.at(0).split(',');
    const QList<QByteArray> first = lines.at(1).split(',');
    QCOMPARE(first.size(), header.size());
    QCOMPARE(first.at(1), QByteArray("3"));
    QCOMPARE(first.at(header.indexOf("commanded_speed_dps")), QByteArray("120.00"));
    QCOMPARE(first.at(header.indexOf("speed_dps")), QByteArray()); // not carried: empty
    QCOMPARE(bus.heard(), QByteArray());
}

void tst_LkctlListen::drivesTellTheLayouts()
{
    // An MS drive reports power where the others report iq: without a read_model reply on
    // the bus it reads as iq, with --drives as power.
    const QByteArray traffic = protocol::encodeFrame(0x9C, 17, {}) +
                               state2Reply(protocol::Command::ReadState2, 17, 10, 100);
    for (const bool named : {false, true}) {
        Bus bus;
        QVERIFY(!bus.port.isEmpty());
        int mode = -1;
        QStringList args{QStringLiteral("--json")};
        if (named)
            args << QStringLiteral("--drives") << QStringLiteral("3:MG,17:MS");
        const CtlResult r = listen(bus, args, traffic, &mode);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject row = QJsonDocument::fromJson(r.out.trimmed()).object();
        QCOMPARE(row.contains(QStringLiteral("power")), named);
        QCOMPARE(row.contains(QStringLiteral("iq_a")), !named);
        QCOMPARE(bus.heard(), QByteArray());
    }
}

void tst_LkctlListen::argumentErrors_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QString>("said");
    QTest::newRow("drive IDs") << "listen 3 --port /dev/null"
                               << "listen takes no drive IDs";
    QTest::newRow("simulated bus") << "listen --sim 3:MF"
                                   << "--sim has no other master";
    QTest::newRow("csv and json") << "listen --port /dev/null --csv --json"
                                  << "--csv and --json exclude each other";
    QTest::newRow("drives") << "listen --port /dev/null --drives 3:XY"
                            << "--drives takes ID:SERIES";
}

void tst_LkctlListen::argumentErrors()
{
    QFETCH(QString, args);
    QFETCH(QString, said);
    const CtlResult r = lk::e2e::lkctl(args.split(QLatin1Char(' ')), 60000);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlListen)
#include "tst_lkctllisten.moc"
