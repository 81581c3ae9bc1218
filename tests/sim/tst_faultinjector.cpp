#include "sim/FaultInjector.h"

#include "SimTestUtil.h"

#include <QtTest/QTest>

using lk::sim::Fault;
using lk::sim::FaultInjector;
using lk::test::hex;

/// Fault injection on encoded replies, seeded, plus its text configuration.
class tst_FaultInjector : public QObject {
    Q_OBJECT
private slots:
    void configureValid_data();
    void configureValid();
    void configureInvalid_data();
    void configureInvalid();
    void nextCountsArePending();
    void noFaultsLeavesReplyAlone();
    void probabilityOneAlwaysFires();
    void aimedDropSkipsOtherReplies();
    void garbageNeverHoldsFrameHead();
    void disconnectFlag();
    void clearResets();
};

void tst_FaultInjector::configureValid_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<double>("drop");
    QTest::addColumn<double>("garbage");
    QTest::addColumn<double>("delaySeconds");
    QTest::addColumn<QList<int>>("silent");
    QTest::newRow("empty") << "" << 0.0 << 0.0 << 0.005 << QList<int>{};
    QTest::newRow("probabilities")
        << "drop=0.01, garbage=0.5" << 0.01 << 0.5 << 0.005 << QList<int>{};
    QTest::newRow("delay and silent")
        << "delay=1,delay_ms=20,silent=3,silent=7,seed=9" << 0.0 << 0.0 << 0.02 << QList<int>{3, 7};
    QTest::newRow("case and blanks") << " DROP = 1 " << 1.0 << 0.0 << 0.005 << QList<int>{};
}

void tst_FaultInjector::configureValid()
{
    QFETCH(QString, spec);
    QFETCH(double, drop);
    QFETCH(double, garbage);
    QFETCH(double, delaySeconds);
    QFETCH(QList<int>, silent);
    FaultInjector f;
    QString error;
    QVERIFY2(f.configure(spec, &error), qPrintable(error));
    QCOMPARE(f.probability(Fault::DropReply), drop);
    QCOMPARE(f.probability(Fault::Garbage), garbage);
    QCOMPARE(f.extraDelaySeconds(), delaySeconds);
    for (int id = 1; id <= 32; ++id)
        QCOMPARE(f.isSilenced(id), silent.contains(id));
}

void tst_FaultInjector::configureInvalid_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("unknown") << "explode=1"
                             << "unknown fault 'explode'";
    QTest::newRow("probability > 1") << "drop=1.5"
                                     << "probability 0..1";
    QTest::newRow("probability text") << "corrupt=often"
                                      << "probability 0..1";
    QTest::newRow("negative delay") << "delay_ms=-1"
                                    << "delay_ms";
    QTest::newRow("silent id 0") << "silent=0"
                                 << "ID 1..32";
    QTest::newRow("seed text") << "seed=abc"
                               << "seed";
    QTest::newRow("next negative") << "drop_next=-1"
                                   << "count 0..1000000";
    QTest::newRow("next text") << "corrupt_next=once"
                               << "count 0..1000000";
    QTest::newRow("next unknown") << "explode_next=1"
                                  << "unknown fault 'explode_next'";
    QTest::newRow("next after a good one") << "drop_next=2,silent=40"
                                           << "ID 1..32";
}

void tst_FaultInjector::configureInvalid()
{
    QFETCH(QString, spec);
    QFETCH(QString, mentions);
    FaultInjector f;
    f.setProbability(Fault::CorruptReply, 0.25);
    QString error;
    QVERIFY(!f.configure(QStringLiteral("drop=0.5,") + spec, &error));
    QVERIFY2(error.contains(mentions), qPrintable(error));
    // Nothing changed by a refused configuration.
    QCOMPARE(f.probability(Fault::DropReply), 0.0);
    QCOMPARE(f.probability(Fault::CorruptReply), 0.25);
    QCOMPARE(f.pending(Fault::DropReply), 0);
}

void tst_FaultInjector::nextCountsArePending()
{
    FaultInjector f;
    QString error;
    QVERIFY2(f.configure(QStringLiteral("drop_next=2, corrupt_next=1, drop_next=1"), &error),
             qPrintable(error));
    QCOMPARE(f.pending(Fault::DropReply), 3);
    QCOMPARE(f.pending(Fault::CorruptReply), 1);
    QCOMPARE(f.probability(Fault::DropReply), 0.0);
}

void tst_FaultInjector::noFaultsLeavesReplyAlone()
{
    FaultInjector f;
    QVERIFY(!f.active());
    const QByteArray original = hex("3E 9C 01 07 E2 19 00 00 00 00 10 00 29");
    for (int i = 0; i < 100; ++i) {
        QByteArray r = original;
        double delay = 0;
        QVERIFY(f.apply(r, delay));
        QCOMPARE(r, original);
        QCOMPARE(delay, 0.0);
    }
    for (int k = 0; k < lk::sim::kFaultKinds; ++k)
        QCOMPARE(f.injectedCount(Fault(k)), 0);
}

void tst_FaultInjector::probabilityOneAlwaysFires()
{
    FaultInjector f(3);
    f.setProbability(Fault::DropReply, 1.0);
    QVERIFY(f.active());
    for (int i = 0; i < 10; ++i) {
        QByteArray r = hex("3E 80 01 00 BF");
        double delay = 0;
        QVERIFY(!f.apply(r, delay));
    }
    QCOMPARE(f.injectedCount(Fault::DropReply), 10);
    f.resetCounts();
    QCOMPARE(f.injectedCount(Fault::DropReply), 0);
}

void tst_FaultInjector::aimedDropSkipsOtherReplies()
{
    FaultInjector f;
    f.dropNextRepliesTo(0x30, 2, 2); // read_pid from drive 2, twice
    f.dropNextRepliesTo(0x33, 0, 1); // read_accel from any drive, once
    QVERIFY(f.active());
    QCOMPARE(f.pendingAimedDrops(), 3);
    // True when the reply came through, unchanged: an aimed drop touches nothing else.
    const auto through = [&f](const char *text) {
        QByteArray r = hex(text);
        double delay = 0;
        return f.apply(r, delay) && r == hex(text) && delay == 0;
    };
    QVERIFY(through("3E 9C 02 00 DC"));                      // another command from drive 2
    QVERIFY(through("3E 30 01 06 6F 01 02 03 04 05 06 15")); // read_pid from drive 1
    QVERIFY(!through("3E 30 02 06 70 01 02 03 04 05 06 15"));
    QVERIFY(through("3E 9A 02 00 DA"));
    QVERIFY(!through("3E 30 02 06 70 01 02 03 04 05 06 15"));
    QVERIFY(through("3E 30 02 06 70 01 02 03 04 05 06 15")); // both spent
    QVERIFY(!through("3E 33 05 04 78 20 4E 00 00 6E"));
    QVERIFY(through("3E 33 05 04 78 20 4E 00 00 6E"));
    QCOMPARE(f.pendingAimedDrops(), 0);
    QCOMPARE(f.injectedCount(Fault::DropReply), 3);
    QVERIFY(!f.active());

    f.dropNextRepliesTo(0x30, 1, 1);
    f.clear();
    QCOMPARE(f.pendingAimedDrops(), 0);
}

void tst_FaultInjector::garbageNeverHoldsFrameHead()
{
    FaultInjector f(11);
    f.setProbability(Fault::Garbage, 1.0);
    const QByteArray frame = hex("3E 80 01 00 BF");
    for (int i = 0; i < 500; ++i) {
        QByteArray r = frame;
        double delay = 0;
        QVERIFY(f.apply(r, delay));
        QVERIFY(r.endsWith(frame));
        const QByteArray noise = r.left(r.size() - frame.size());
        QVERIFY(noise.size() >= 1 && noise.size() <= 8);
        QVERIFY(!noise.contains('\x3E'));
    }
}

void tst_FaultInjector::disconnectFlag()
{
    FaultInjector f;
    QVERIFY(!f.disconnectRequested());
    f.requestDisconnect();
    QVERIFY(f.disconnectRequested());
    QVERIFY(f.takeDisconnect());
    QVERIFY(!f.takeDisconnect());
}

void tst_FaultInjector::clearResets()
{
    FaultInjector f;
    QVERIFY(f.configure(QStringLiteral("drop=0.5,corrupt=0.5,silent=4")));
    f.injectNext(Fault::Garbage, 3);
    QCOMPARE(f.pending(Fault::Garbage), 3);
    QVERIFY(f.active());
    f.clear();
    QVERIFY(!f.active());
    QCOMPARE(f.pending(Fault::Garbage), 0);
    QVERIFY(!f.isSilenced(4));
}

QTEST_APPLESS_MAIN(tst_FaultInjector)
#include "tst_faultinjector.moc"
