// LinkTiming: the RS485 link keeps BusTiming's figures exactly; the CAN link counts the bits
// of a classic 8-byte frame with worst-case stuffing and the 0.25 ms reply time. Expected
// figures are worked out by hand in the comments, not taken from the code.

#include <bus/BusTiming.h>
#include <bus/LinkTiming.h>

#include <QtTest/QTest>

using lk::bus::BusTiming;
using lk::bus::LinkTiming;
using lk::protocol::Command;

class tst_LinkTiming : public QObject {
    Q_OBJECT
private slots:
    void canFrameBits_data();
    void canFrameBits();
    void canTransaction_data();
    void canTransaction();
    void rs485IsBusTiming_data();
    void rs485IsBusTiming();
    void canBitRates();
    void replyTimeout();
};

void tst_LinkTiming::canFrameBits_data()
{
    QTest::addColumn<int>("dataBytes");
    QTest::addColumn<int>("bits");
    QTest::addColumn<int>("stuffed");
    // 47 + 8n; stuff region 34 + 8n bits, at most (34 + 8n - 1) / 4 stuff bits.
    QTest::newRow("8 bytes: 111, up to 135") << 8 << 111 << 135;
    QTest::newRow("0 bytes: 47, up to 55") << 0 << 47 << 55;
    QTest::newRow("1 byte: 55, up to 65") << 1 << 55 << 65;
}

void tst_LinkTiming::canFrameBits()
{
    QFETCH(int, dataBytes);
    QFETCH(int, bits);
    QFETCH(int, stuffed);
    QCOMPARE(LinkTiming::canFrameBits(dataBytes), bits);
    QCOMPARE(LinkTiming::canFrameBitsStuffed(dataBytes), stuffed);
}

void tst_LinkTiming::canTransaction_data()
{
    QTest::addColumn<int>("bitRate");
    QTest::addColumn<double>("wireS");
    QTest::addColumn<double>("perSecond");
    // Request and reply 135 bits each: 270 bits, + 0.25 ms.
    QTest::newRow("1 Mbit/s: 0.27 ms + 0.25 ms -> 1923/s") << 1000000 << 270e-6 << 1 / 520e-6;
    QTest::newRow("500 kbit/s: 0.54 ms + 0.25 ms -> 1266/s") << 500000 << 540e-6 << 1 / 790e-6;
    QTest::newRow("125 kbit/s: 2.16 ms + 0.25 ms -> 415/s") << 125000 << 2160e-6 << 1 / 2410e-6;
}

void tst_LinkTiming::canTransaction()
{
    QFETCH(int, bitRate);
    QFETCH(double, wireS);
    QFETCH(double, perSecond);
    const LinkTiming t = LinkTiming::can(bitRate);
    QCOMPARE(int(t.link()), int(lk::protocol::Link::Can));
    QCOMPARE(t.bitRate(), bitRate);
    QCOMPARE(t.turnaroundS(), 0.00025);
    // Every command is 8 bytes both ways on CAN, whatever its RS485 length.
    for (Command c : {Command::ReadState2, Command::ReadMultiTurn, Command::MotorOff,
                      Command::MultiPositionLimited}) {
        QVERIFY(qAbs(t.wireTimeS(c) - wireS) < 1e-12);
        QVERIFY(qAbs(t.transactionTimeS(c) - (wireS + 0.00025)) < 1e-12);
    }
    const QVector<Command> mix{Command::ReadState2, Command::ReadState1, Command::ReadMultiTurn};
    QVERIFY(qAbs(t.transactionsPerSecond(mix) - perSecond) < 1e-6);
    QCOMPARE(t.transactionsPerSecond({}), 0.0);
}

void tst_LinkTiming::rs485IsBusTiming_data()
{
    QTest::addColumn<int>("baud");
    QTest::newRow("115200") << 115200;
    QTest::newRow("9600") << 9600;
    QTest::newRow("4000000") << 4000000;
}

void tst_LinkTiming::rs485IsBusTiming()
{
    QFETCH(int, baud);
    const LinkTiming t = LinkTiming::rs485(baud);
    QCOMPARE(t.turnaroundS(), BusTiming::kTurnaroundS);
    for (Command c : {Command::ReadState2, Command::ReadModel, Command::MotorOff,
                      Command::MultiPositionLimited, Command::WriteParamRom}) {
        QCOMPARE(t.transactionTimeS(c), BusTiming::transactionTimeS(c, baud));
        QCOMPARE(t.replyTimeoutS(c, 0.002), BusTiming::replyTimeoutS(c, baud, 0.002));
        QCOMPARE(t.maxReplyWireS(c), BusTiming::wireTimeS(0, BusTiming::maxReplyBytes(c), baud));
    }
    const QVector<Command> mix{Command::ReadState2, Command::ReadState1, Command::ReadState3};
    QCOMPARE(t.transactionsPerSecond(mix), BusTiming::transactionsPerSecond(mix, baud));
    QCOMPARE(t.transactionsPerSecond(mix, 0.0), BusTiming::transactionsPerSecond(mix, baud, 0.0));
    // The worked example of docs/ARCHITECTURE.md: 485 transactions a second at 115200.
    QCOMPARE(qRound(LinkTiming::rs485(115200).transactionsPerSecond({Command::ReadState2})), 485);
}

void tst_LinkTiming::canBitRates()
{
    QCOMPARE(LinkTiming::canBitRates().front(), LinkTiming::kCanDefaultBitRate);
    for (int r : {1000000, 500000, 250000, 125000, 100000})
        QVERIFY(LinkTiming::isCanBitRate(r));
    for (int r : {115200, 800000, 0, -1})
        QVERIFY(!LinkTiming::isCanBitRate(r));
}

void tst_LinkTiming::replyTimeout()
{
    // 135 + 135 bits at 1 Mbit/s + 0.25 ms + 2 ms margin.
    QVERIFY(qAbs(LinkTiming::can(1000000).replyTimeoutS(Command::ReadState2, 0.002) -
                 (270e-6 + 250e-6 + 0.002)) < 1e-12);
    QCOMPARE(LinkTiming::can(0).wireTimeS(Command::ReadState2), 0.0);
}

QTEST_APPLESS_MAIN(tst_LinkTiming)
#include "tst_linktiming.moc"
