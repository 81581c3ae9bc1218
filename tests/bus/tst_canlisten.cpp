// Listen-only on CAN: the passive path reads the CAN transport's records. Requests travel on
// 0x140+ID, replies on 0x140+ID (old generation) or 0x180+ID (V2.36); a reply's layout or ID
// tells it from a request, and an echo command on the shared ID is told by order. The decoded
// values equal what the frames carry, a reply on 0x180+ID names its drive V2.36, error frames
// are counted, and nothing is written: neither by the engine nor by a CanTransport opened
// read-only (checked against Qt's virtualcan, on a TCP port of this test's own).

#include "../support/ManualTimers.h"
#include "BusTestUtil.h"

#include <bus/BusDiagnostics.h>
#include <bus/BusMetaTypes.h>
#include <bus/ListenMonitor.h>
#include <bus/ListenStatistics.h>
#include <bus/MotorRegistry.h>
#include <bus/TelemetryBatcher.h>
#include <protocol/CanRecord.h>
#include <transport/CanTransport.h>

#include <QtNetwork/QTcpServer>
#include <QtSerialBus/QCanBus>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using protocol::Generation;

namespace {

QByteArray record(quint32 canId, const char *hex)
{
    return protocol::CanRecord::of({canId, QByteArray::fromHex(hex)}).encode();
}

QByteArray errorRecord()
{
    protocol::CanRecord r;
    r.canId = 0x20000080; // CAN_ERR_FLAG | CAN_ERR_BUSERROR
    r.flags = protocol::CanRecord::Error;
    r.data = QByteArray(8, '\0');
    return r.encode();
}

/// The passive path alone, on a clock the test sets.
struct Monitor {
    Monitor()
    {
        motors.setLink(protocol::Link::Can);
        monitor.restart(protocol::Link::Can);
        QObject::connect(&batcher, &TelemetryBatcher::batchReady,
                         [this](const TelemetryBatch &b) { samples += b; });
    }
    void hear(const QByteArray &bytes, double atMs)
    {
        clock->setNs(qint64(atMs * 1e6));
        monitor.feed(bytes, 1000000);
        batcher.flush();
    }
    TelemetrySample only(int id, TelemetryField field) const
    {
        for (const TelemetrySample &s : samples)
            if (s.id == id && s.has(field))
                return s;
        return {};
    }

    std::shared_ptr<testsupport::ManualClock> clock = std::make_shared<testsupport::ManualClock>();
    MotorRegistry motors;
    TelemetryBatcher batcher;
    BusDiagnostics diagnostics{motors, clock, makeQtSingleShotTimer};
    ListenMonitor monitor{motors, batcher, diagnostics, clock};
    TelemetryBatch samples;
};

/// A CAN link another master drives: what the test says arrives, what is written is kept.
class CanTap : public transport::Transport {
public:
    bool open() override
    {
        m_state = State::Open;
        emit stateChanged(m_state);
        return true;
    }
    void close() override { m_state = State::Closed; }
    void write(const QByteArray &bytes) override { written += bytes; }
    State state() const override { return m_state; }
    int baud() const override { return 1000000; }
    QString description() const override { return QStringLiteral("CAN tap"); }
    protocol::Link link() const override { return protocol::Link::Can; }
    void hear(const QByteArray &bytes) { emit bytesReceived(bytes); }

    QByteArray written;

private:
    State m_state = State::Closed;
};

quint16 freePort()
{
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0))
        return 0;
    return probe.serverPort();
}

} // namespace

class tst_CanListen : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void decodesBothGenerations();
    void statisticsOnCan();
    void anotherMastersMultiTorque();
    void anotherMastersTorqueBeyondOursIsHeard();
    void listeningWorkerOnACanLink();
    void readOnlyCanTransportSendsNothing();
};

void tst_CanListen::decodesBothGenerations()
{
    Monitor m;
    // Drive 1, old CAN: request and reply share 0x141. Temp 30, iq 100, 10 dps, encoder 10000.
    m.hear(record(0x141, "9C00000000000000"), 1.0);
    m.hear(record(0x141, "9C1E64000A001027"), 1.3);
    // Drive 2, V2.36 as its document says: the reply on 0x182.
    m.hear(record(0x142, "9C00000000000000"), 2.0);
    m.hear(record(0x182, "9C1E9CFFF6FF2003"), 2.3);
    // The other master's speed to drive 1 (old layout: 100.00 dps) and the motion reply.
    m.hear(record(0x141, "A200000010270000"), 3.0);
    m.hear(record(0x141, "A21E64000A001027"), 3.3);
    QCOMPARE(m.motors.all().value(2).generation, Generation::V2_35);
    QVERIFY(m.motors.all().contains(1));
    const TelemetrySample s1 = m.only(1, TelemetryField::Speed);
    QCOMPARE(s1.speedDps, 10.0);
    QCOMPARE(s1.temperatureC, 30);
    QCOMPARE(s1.encoder, 10000);
    const TelemetrySample s2 = m.only(2, TelemetryField::Speed);
    QCOMPARE(s2.speedDps, -10.0);
    QCOMPARE(s2.encoder, 800);
    const TelemetrySample commanded = m.only(1, TelemetryField::CommandedSpeed);
    QCOMPARE(commanded.commandedSpeedDps, 100.0);
    // The request is no reply: no sample of its zeros, none of its speed read as a reply's.
    int speeds1 = 0;
    for (const TelemetrySample &s : m.samples)
        speeds1 += s.id == 1 && s.has(TelemetryField::Speed) ? 1 : 0;
    QCOMPARE(speeds1, 2); // the 0x9C reply and the 0xA2 motion reply
    QCOMPARE(m.monitor.counts().paired, quint64(3));
    QCOMPARE(m.monitor.counts().requests, quint64(3));
}

void tst_CanListen::statisticsOnCan()
{
    Monitor m;
    m.monitor.snapshot(1000000); // the period starts here
    double t = 0;
    for (int i = 0; i < 10; ++i) {
        m.hear(record(0x141, "9C00000000000000"), t += 1);
        m.hear(record(0x141, "9C1E64000A001027"), t += 0.25);
    }
    m.hear(record(0x143, "9A00000000000000"), t += 1); // no drive 3
    m.hear(errorRecord(), t += 1);
    m.hear(record(0x141, "8000000000000000"), t += 1); // motor_off and its echo
    m.hear(record(0x141, "8000000000000000"), t += 0.25);
    m.clock->setNs(qint64(1e9)); // one second in all
    const ListenStatistics s = m.monitor.snapshot(1000000);
    QCOMPARE(s.requests, quint64(12));
    QCOMPARE(s.paired, quint64(11));
    QCOMPARE(s.unanswered, quint64(1)); // drive 3's: the next request showed it
    QCOMPARE(s.canErrorFrames, quint64(1));
    QCOMPARE(s.perDrive.value(1).replies, quint64(11));
    QCOMPARE(s.perDrive.value(1).latency.medianMs, 0.25);
    // 23 data frames of 111 bits (unstuffed) at 1 Mbit/s in one second, plus the error frame.
    QCOMPARE(s.busLoad, 24 * 111 / 1e6);
}

void tst_CanListen::anotherMastersMultiTorque()
{
    // A robot controller commanding drives 1..4 with the old generation's 0x280 frame: each
    // slot is its torque command to the drive of that ID, and each drive's 0xA1 reply pairs
    // with it (docs/CAN.md 4.2: the vector "ID 1 +100, ID 2 -100").
    Monitor m;
    TrafficBatch traffic;
    QObject::connect(&m.diagnostics, &BusDiagnostics::trafficCaptured,
                     [&traffic](const TrafficBatch &b) { traffic += b; });
    m.diagnostics.setTrafficCapture(true);
    m.monitor.snapshot(1000000);
    // Drives 1 and 2 are seen first (a state read each); 3 and 4 never are.
    m.hear(record(0x141, "9C00000000000000"), 1.0);
    m.hear(record(0x141, "9C1E64000A001027"), 1.25);
    m.hear(record(0x142, "9C00000000000000"), 2.0);
    m.hear(record(0x142, "9C1E64000A001027"), 2.25);
    m.motors.setSeries(1, protocol::Series::MF);
    m.motors.setSeries(2, protocol::Series::MG);
    m.hear(record(0x280, "64009CFF00000000"), 3.0);
    // Both answer in ID order: temp 30, iq +-100, 10 dps, encoder 10000.
    m.hear(record(0x141, "A11E64000A001027"), 3.25);
    m.hear(record(0x142, "A11E9CFF0A001027"), 3.5);
    const TelemetrySample c1 = m.only(1, TelemetryField::CommandedIq);
    const TelemetrySample c2 = m.only(2, TelemetryField::CommandedIq);
    QVERIFY(c1.has(TelemetryField::CommandedIq) && c2.has(TelemetryField::CommandedIq));
    QCOMPARE(c1.commandedIqA, 100 * 32.0 / 2000); // V2.3's scale: 1.60 A
    QCOMPARE(c2.commandedIqA, -100 * 32.0 / 2000);
    QCOMPARE(c1.time, 0.003);
    for (int id : {3, 4}) // no drive seen there: no command to one
        QVERIFY(!m.only(id, TelemetryField::CommandedIq).has(TelemetryField::CommandedIq));
    // The replies are paired with their slots, not orphans; the speeds are the drives'.
    QCOMPARE(m.monitor.counts().orphanReplies, quint64(0));
    QCOMPARE(m.monitor.counts().paired, quint64(4));
    QCOMPARE(m.monitor.counts().requests, quint64(4));
    int replies = 0;
    for (const TelemetrySample &s : m.samples)
        replies += s.has(TelemetryField::Speed) && s.time > 0.0031 ? 1 : 0;
    QCOMPARE(replies, 2);
    // Drive 2 stays silent on the next frame: once its window has passed it is the other
    // master's timeout, named by drive and command; drive 1's answer pairs.
    m.hear(record(0x280, "0A00F6FF00000000"), 4.0);
    m.hear(record(0x141, "A11E0A000A001027"), 4.25);
    m.clock->setNs(qint64(1e9));
    const ListenStatistics s = m.monitor.snapshot(1000000);
    QCOMPARE(s.requests, quint64(6));
    QCOMPARE(s.paired, quint64(5));
    QCOMPARE(s.unanswered, quint64(1));
    QCOMPARE(s.perDrive.value(2).unanswered, quint64(1));
    QCOMPARE(s.perCommand.value(0xA1).requests, quint64(4));
    QCOMPARE(s.perDrive.value(1).latency.medianMs, 0.25);
    QCOMPARE(s.otherFrames, quint64(2)); // the 0x280 frames themselves, as before
    // The Traffic view gets each 0x280 as a received frame with its record's bytes.
    const auto multiTorques = [&traffic] {
        int n = 0;
        for (const TrafficEvent &e : traffic)
            n += e.kind == TrafficEvent::Kind::Frame &&
                         e.bytes == record(0x280, "64009CFF00000000") && e.context.onCan()
                     ? 1
                     : 0;
        return n;
    };
    QTRY_COMPARE(multiTorques(), 1); // delivered every 50 ms
}

void tst_CanListen::anotherMastersTorqueBeyondOursIsHeard()
{
    // We never send beyond +-2000 (32 A) in a 0x280 slot; another master may (2047), and its
    // drive answers it: the command is heard as sent and the reply pairs, no orphan.
    Monitor m;
    m.hear(record(0x141, "9C00000000000000"), 1.0);
    m.hear(record(0x141, "9C1E64000A001027"), 1.25);
    m.motors.setSeries(1, protocol::Series::MF);
    m.hear(record(0x280, "FF07000000000000"), 2.0);
    m.hear(record(0x141, "A11EFF070A001027"), 2.25);
    const TelemetrySample c = m.only(1, TelemetryField::CommandedIq);
    QVERIFY(c.has(TelemetryField::CommandedIq));
    QCOMPARE(c.commandedIqA, 2047 * 32.0 / 2000);
    QCOMPARE(m.monitor.counts().orphanReplies, quint64(0));
    QCOMPARE(m.monitor.counts().paired, quint64(2));
}

void tst_CanListen::listeningWorkerOnACanLink()
{
    testsupport::ManualTimers timers(std::make_shared<testsupport::ManualClock>());
    CanTap *tap = nullptr;
    BusWorker worker(
        [&tap](int) {
            auto t = std::make_unique<CanTap>();
            tap = t.get();
            return t;
        },
        1000000, bustest::relaxedConfig(), timers.timeSource());
    TelemetryBatch samples;
    QObject::connect(&worker, &BusWorker::telemetryReceived,
                     [&samples](const TelemetryBatch &b) { samples += b; });
    worker.start(LinkMode::ListenOnly);
    QVERIFY(tap);
    tap->hear(record(0x145, "9C00000000000000"));
    timers.advance(0.3);
    tap->hear(record(0x185, "9C1E64000A001027"));
    timers.advance(200);
    QVERIFY(worker.knownMotors().contains(5));
    QCOMPARE(worker.knownMotors().value(5).generation, Generation::V2_35);
    QCOMPARE(samples.size(), 1);
    QCOMPARE(samples.at(0).speedDps, 10.0);
    worker.emergencyStop(1, {5}); // refused in listen-only: nothing reaches the wire
    timers.advance(2000);
    QCOMPARE(tap->written.size(), 0);
}

void tst_CanListen::readOnlyCanTransportSendsNothing()
{
    const quint16 port = freePort();
    QVERIFY(port != 0);
    const QString url = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
    QString error;
    std::unique_ptr<QCanBusDevice> other(
        QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), url, &error));
    QVERIFY2(other, qPrintable(error));
    QVERIFY(other->connectDevice());
    QTRY_COMPARE(other->state(), QCanBusDevice::ConnectedState);
    transport::CanSettings settings;
    settings.plugin = QStringLiteral("virtualcan");
    settings.interfaceName = url;
    for (const bool readOnly : {false, true}) {
        transport::CanTransport t(settings);
        t.setReadOnly(readOnly);
        QVERIFY(t.open());
        QTRY_COMPARE(t.state(), transport::Transport::State::Open);
        QTest::qWait(100); // connected on the server's side too
        other->readAllFrames();
        t.write(record(0x141, "8000000000000000"));
        QTest::qWait(300);
        const QList<QCanBusFrame> heard = other->readAllFrames();
        // Active: the frame reaches the bus (the check can fail); listen-only: nothing does.
        QCOMPARE(heard.size(), readOnly ? 0 : 1);
        QCOMPARE(t.refusedWrites(), readOnly ? quint64(protocol::CanRecord::kSize) : 0);
        t.close();
    }
}

QTEST_GUILESS_MAIN(tst_CanListen)
#include "tst_canlisten.moc"
