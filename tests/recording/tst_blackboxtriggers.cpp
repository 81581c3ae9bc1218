// BlackBoxTriggers: when the black box saves, from session events alone.
#include <recording/BlackBoxTriggers.h>

#include <QtTest/QtTest>

using lk::recording::BlackBoxTriggers;
using Reason = BlackBoxTriggers::Reason;

namespace {

constexpr qint64 kS = 1'000'000'000;

} // namespace

class tst_BlackBoxTriggers : public QObject {
    Q_OBJECT
private slots:
    void emergencyStopAlwaysSaves()
    {
        BlackBoxTriggers t;
        QCOMPARE(t.emergencyStop(1 * kS), Reason::EmergencyStop);
        QCOMPARE(t.emergencyStop(2 * kS), Reason::EmergencyStop); // no holdoff for a stop
        QCOMPARE(t.linkLost(3 * kS), std::nullopt);               // held off by the stop
        QCOMPARE(t.linkLost(40 * kS), Reason::LinkLost);
    }

    void aNewFaultFlagSaves_data()
    {
        QTest::addColumn<QVector<quint32>>("flags");
        QTest::addColumn<QVector<bool>>("saves");
        QTest::newRow("first report clean") << QVector<quint32>{0, 0} << QVector<bool>{0, 0};
        QTest::newRow("first report faulty") << QVector<quint32>{0x08} << QVector<bool>{1};
        QTest::newRow("same flag again")
            << QVector<quint32>{0, 0x08, 0x08} << QVector<bool>{0, 1, 0};
        QTest::newRow("a flag clears") << QVector<quint32>{0x09, 0x01} << QVector<bool>{1, 0};
        QTest::newRow("cleared then back")
            << QVector<quint32>{0x08, 0, 0x08} << QVector<bool>{1, 0, 1};
        QTest::newRow("another flag joins") << QVector<quint32>{0x01, 0x09} << QVector<bool>{1, 1};
    }
    void aNewFaultFlagSaves()
    {
        QFETCH(QVector<quint32>, flags);
        QFETCH(QVector<bool>, saves);
        BlackBoxTriggers::Settings s;
        s.holdoffNs = 0;
        BlackBoxTriggers t(s);
        for (int i = 0; i < flags.size(); ++i)
            QCOMPARE(t.faultFlags(3, flags[i], i * kS).has_value(), saves[i]);
        // Another drive has its own history.
        QCOMPARE(t.faultFlags(4, 0x01, 100 * kS), Reason::FaultFlag);
    }

    void aTimeoutBurstSaves_data()
    {
        QTest::addColumn<QVector<double>>("times"); ///< seconds
        QTest::addColumn<int>("savesAt");           ///< index of the saving timeout, -1: none
        QTest::newRow("5 in 2 s") << QVector<double>{0, 0.4, 0.8, 1.2, 1.6} << 4;
        QTest::newRow("4 in 2 s") << QVector<double>{0, 0.4, 0.8, 1.2} << -1;
        QTest::newRow("5 spread over 10 s") << QVector<double>{0, 2.5, 5, 7.5, 10} << -1;
        QTest::newRow("a slow start, then a burst")
            << QVector<double>{0, 3, 10, 10.1, 10.2, 10.3, 10.4} << 6;
    }
    void aTimeoutBurstSaves()
    {
        QFETCH(QVector<double>, times);
        QFETCH(int, savesAt);
        BlackBoxTriggers t;
        for (int i = 0; i < times.size(); ++i) {
            const auto r = t.timeout(qint64(times[i] * kS));
            QCOMPARE(r.has_value(), i == savesAt);
            if (r)
                QCOMPARE(*r, Reason::TimeoutBurst);
        }
    }

    void oneIncidentSavesOnce()
    {
        BlackBoxTriggers t; // 30 s holdoff
        QCOMPARE(t.linkLost(10 * kS), Reason::LinkLost);
        for (int i = 0; i < 10; ++i)
            QCOMPARE(t.timeout(10 * kS + i * kS / 10), std::nullopt);
        QCOMPARE(t.faultFlags(1, 0x04, 20 * kS), std::nullopt);
        QCOMPARE(t.faultFlags(1, 0x0C, 41 * kS), Reason::FaultFlag);
    }
};

QTEST_APPLESS_MAIN(tst_BlackBoxTriggers)
#include "tst_blackboxtriggers.moc"
