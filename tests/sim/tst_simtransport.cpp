#include "transport/SimTransport.h"

#include "SimTestUtil.h"
#include "sim/SimBus.h"

#include <QtCore/QElapsedTimer>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using lk::sim::SimBus;
using lk::test::hex;
using lk::transport::SimTransport;
using lk::transport::Transport;
using lk::transport::TransportError;

namespace {
constexpr int kWaitMs = 10000; // generous: the machine may be loaded

std::unique_ptr<SimTransport> makeTransport(const char *spec = "1:MF,2:MS,3:MG")
{
    return std::make_unique<SimTransport>(
        SimBus::fromSpec(*sim::SimBusSpec::parse(QString::fromLatin1(spec))));
}

/// An open transport answering after `replyDelay` s, plus the wire time of `baud` (0: none).
std::unique_ptr<SimTransport> openTransport(double replyDelay, int baud)
{
    auto t = makeTransport();
    t->setReplyDelay(replyDelay);
    if (baud > 0) {
        t->setBaud(baud);
        t->setWireTimeEmulation(true);
    }
    t->open();
    return t;
}

const QByteArray kRead1 = hex("3E 9C 01 00 DB");
} // namespace

/// The in-process simulated transport: delivery, delays, faults, state.
class tst_SimTransport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void openWriteReceive();
    void describesItself();
    void closedDropsWrites();
    void repliesInOrder();
    void delayHonoured_data();
    void delayHonoured();
    void waitsWithoutSpinning_data();
    void waitsWithoutSpinning();
    void closeDropsPending();
    void disconnectOnWrite();
    void disconnectWhileIdle();
    void benchmarkZeroDelayRoundTrips();
};

void tst_SimTransport::initTestCase()
{
    qRegisterMetaType<TransportError>();
    qRegisterMetaType<Transport::State>();
}

void tst_SimTransport::openWriteReceive()
{
    auto t = makeTransport();
    QSignalSpy states(t.get(), &Transport::stateChanged);
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    QCOMPARE(t->state(), Transport::State::Closed);
    QVERIFY(t->open());
    QCOMPARE(t->state(), Transport::State::Open);
    QCOMPARE(states.size(), 1);
    QCOMPARE(states.first().first().value<Transport::State>(), Transport::State::Open);
    QVERIFY(t->open()); // already open: no second signal
    QCOMPARE(states.size(), 1);

    t->write(kRead1);
    QCOMPARE(bytes.size(), 0); // never delivered inside write()
    QTRY_COMPARE_WITH_TIMEOUT(bytes.size(), 1, kWaitMs);
    const QByteArray reply = bytes.first().first().toByteArray();
    QCOMPARE(reply.size(), 13);
    QCOMPARE(reply.left(3), hex("3E 9C 01"));
    QCOMPARE(t->bus().requestCount(1), 1);

    t->write(hex("3E 9C 09 00 E3")); // no drive 9: silence
    QTest::qWait(50);
    QCOMPARE(bytes.size(), 1);
}

void tst_SimTransport::describesItself()
{
    auto t = makeTransport();
    QCOMPARE(t->description(), QStringLiteral("Simulated bus (3 drives)"));
    QCOMPARE(makeTransport("4:MH")->description(), QStringLiteral("Simulated bus (1 drive)"));
    QCOMPARE(t->baud(), 115200);
    t->setBaud(9600);
    QCOMPARE(t->baud(), 9600);
    t->setBaud(0);
    QCOMPARE(t->baud(), 9600);
    QCOMPARE(t->replyDelay(), 0.0002);
    t->setReplyDelay(0.001);
    QCOMPARE(t->bus().replyDelay(), 0.001);
}

void tst_SimTransport::closedDropsWrites()
{
    auto t = makeTransport();
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    t->write(kRead1);
    QTest::qWait(50);
    QCOMPARE(bytes.size(), 0);
    QCOMPARE(t->bus().counters().requests, 0); // never reached the bus
}

void tst_SimTransport::repliesInOrder()
{
    auto t = makeTransport();
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    t->open();
    t->setReplyDelay(0.0);
    t->write(kRead1 + hex("3E 9C 02 00 DC 3E 9C 03 00 DD"));
    QTRY_COMPARE_WITH_TIMEOUT(bytes.size(), 3, kWaitMs);
    for (int i = 0; i < 3; ++i)
        QCOMPARE(int(bytes[i].first().toByteArray().at(2)), i + 1);
}

void tst_SimTransport::delayHonoured_data()
{
    QTest::addColumn<double>("replyDelay");
    QTest::addColumn<int>("baud"); // 0 = no wire-time emulation
    QTest::addColumn<double>("expectedMin");
    QTest::newRow("0.2 ms default") << 0.0002 << 0 << 0.0002;
    QTest::newRow("0.7 ms") << 0.0007 << 0 << 0.0007;
    QTest::newRow("3 ms") << 0.003 << 0 << 0.003;
    QTest::newRow("20 ms") << 0.02 << 0 << 0.02;
    // (5 + 13 bytes) x 10 bits at 9600 baud = 18.75 ms, plus the turnaround.
    QTest::newRow("wire 9600") << 0.0005 << 9600 << 0.01925;
    QTest::newRow("wire 115200") << 0.0005 << 115200 << 0.0020625;
}

void tst_SimTransport::delayHonoured()
{
    QFETCH(double, replyDelay);
    QFETCH(int, baud);
    QFETCH(double, expectedMin);
    auto t = openTransport(replyDelay, baud);
    qint64 arrivedNs = -1;
    QElapsedTimer clock;
    connect(t.get(), &Transport::bytesReceived, this, [&] { arrivedNs = clock.nsecsElapsed(); });
    for (int round = 0; round < 5; ++round) {
        arrivedNs = -1;
        clock.start();
        t->write(kRead1);
        QTRY_VERIFY_WITH_TIMEOUT(arrivedNs >= 0, kWaitMs);
        // Only a lower bound: a loaded machine may deliver late, never early.
        QVERIFY2(arrivedNs >= qint64(expectedMin * 1e9),
                 qPrintable(QStringLiteral("%1 ns").arg(arrivedNs)));
    }
}

void tst_SimTransport::waitsWithoutSpinning_data()
{
    QTest::addColumn<double>("replyDelay");
    QTest::addColumn<int>("baud"); // 0 = no wire-time emulation
    // Under a millisecond (what a CAN frame or a fast RS485 reply waits): QTimer cannot wait
    // that precisely, and looking on every turn of the event loop kept a core busy.
    QTest::newRow("0.2 ms") << 0.0002 << 0;
    QTest::newRow("0.7 ms") << 0.0007 << 0;
    QTest::newRow("wire 1 Mbaud") << 0.0002 << 1000000;
    QTest::newRow("3 ms") << 0.003 << 0;
}

void tst_SimTransport::waitsWithoutSpinning()
{
    QFETCH(double, replyDelay);
    QFETCH(int, baud);
    auto t = openTransport(replyDelay, baud);
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    constexpr int kRounds = 50;
    const int before = t->wakeups();
    for (int round = 0; round < kRounds; ++round) {
        t->write(kRead1);
        QVERIFY(bytes.size() > round || bytes.wait(kWaitMs));
    }
    // One look per reply when it is due; a few more if the clock and the wake-up disagree by
    // a rounding. Polling looked hundreds of times per reply.
    const int looks = t->wakeups() - before;
    QVERIFY2(looks <= 3 * kRounds, qPrintable(QStringLiteral("%1 looks").arg(looks)));
}

void tst_SimTransport::closeDropsPending()
{
    auto t = makeTransport();
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    QSignalSpy states(t.get(), &Transport::stateChanged);
    t->setReplyDelay(0.03);
    t->open();
    t->write(kRead1);
    QCOMPARE(t->pendingReplies(), 1);
    t->close();
    QCOMPARE(t->state(), Transport::State::Closed);
    QCOMPARE(t->pendingReplies(), 0);
    QTest::qWait(100);
    QCOMPARE(bytes.size(), 0);
    QCOMPARE(states.size(), 2);
}

void tst_SimTransport::disconnectOnWrite()
{
    auto t = makeTransport();
    QSignalSpy states(t.get(), &Transport::stateChanged);
    QSignalSpy errors(t.get(), &Transport::errorOccurred);
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    t->open();
    t->bus().faults().requestDisconnect();
    t->write(kRead1);
    QCOMPARE(t->state(), Transport::State::Disconnected);
    QCOMPARE(states.last().first().value<Transport::State>(), Transport::State::Disconnected);
    QCOMPARE(errors.size(), 1);
    const auto error = errors.first().first().value<TransportError>();
    QCOMPARE(error.kind, TransportError::Kind::Unplugged);
    QVERIFY(!error.message.isEmpty());
    QCOMPARE(t->bus().counters().requests, 0);

    t->write(kRead1); // disconnected: dropped, no second error
    QTest::qWait(50);
    QCOMPARE(bytes.size(), 0);
    QCOMPARE(errors.size(), 1);

    QVERIFY(t->open()); // reconnect
    QCOMPARE(t->state(), Transport::State::Open);
    t->write(kRead1);
    QTRY_COMPARE_WITH_TIMEOUT(bytes.size(), 1, kWaitMs);
}

void tst_SimTransport::disconnectWhileIdle()
{
    auto t = makeTransport();
    QSignalSpy errors(t.get(), &Transport::errorOccurred);
    t->open();
    t->bus().faults().requestDisconnect(); // no write follows: housekeeping notices
    QTRY_COMPARE_WITH_TIMEOUT(errors.size(), 1, kWaitMs);
    QCOMPARE(t->state(), Transport::State::Disconnected);
}

void tst_SimTransport::benchmarkZeroDelayRoundTrips()
{
    // A figure, not a pass/fail speed test: round trips per second with no delay, one
    // request outstanding at a time, as a bus engine would run it.
    auto t = makeTransport();
    t->setReplyDelay(0.0);
    t->open();
    constexpr int kRounds = 20000;
    int received = 0;
    connect(t.get(), &Transport::bytesReceived, this, [&] {
        if (++received < kRounds)
            t->write(kRead1);
    });
    QElapsedTimer clock;
    clock.start();
    t->write(kRead1);
    QTRY_COMPARE_WITH_TIMEOUT(received, kRounds, 120000);
    const double seconds = clock.nsecsElapsed() / 1e9;
    qInfo("SimTransport zero-delay round trips: %d in %.3f s = %.0f transactions/s", kRounds,
          seconds, kRounds / seconds);
    QCOMPARE(t->bus().counters().replies, qint64(kRounds));
}

QTEST_GUILESS_MAIN(tst_SimTransport)
#include "tst_simtransport.moc"
