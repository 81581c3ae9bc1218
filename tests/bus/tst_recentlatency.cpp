#include <bus/RecentLatency.h>

#include <QtTest/QTest>

using lk::bus::RecentLatency;

/// How soon a reply can come, from the wire time and the recent replies.
class tst_RecentLatency : public QObject {
    Q_OBJECT
private slots:
    void earliestReply_data();
    void earliestReply();
    void windowForgetsOldSamples();
};

void tst_RecentLatency::earliestReply_data()
{
    QTest::addColumn<QVector<double>>("samples");
    QTest::addColumn<double>("wireS");
    QTest::addColumn<double>("earliestS");
    QTest::newRow("nothing measured") << QVector<double>{} << 0.0015 << 0.0;
    QTest::newRow("real wire: the wire bounds it")
        << QVector<double>{0.0021, 0.0022, 0.0021} << 0.0015 << 0.0015;
    QTest::newRow("no wire (in-process): 90 % of the median")
        << QVector<double>{0.0002, 0.0003, 0.0002} << 0.0015 << 0.00018;
    // Stale replies taken for fresh ones (1.1 ms) are a minority: the median ignores them.
    QTest::newRow("a few stale replies do not lower the bar")
        << QVector<double>{0.0021, 0.0011, 0.0022, 0.0011, 0.0021} << 0.0015 << 0.0015;
}

void tst_RecentLatency::earliestReply()
{
    QFETCH(QVector<double>, samples);
    QFETCH(double, wireS);
    QFETCH(double, earliestS);
    RecentLatency r;
    for (double s : samples)
        r.add(s);
    QVERIFY2(qAbs(r.earliestReplyS(wireS) - earliestS) < 1e-9,
             qPrintable(QString::number(r.earliestReplyS(wireS))));
}

void tst_RecentLatency::windowForgetsOldSamples()
{
    RecentLatency r;
    for (size_t i = 0; i < RecentLatency::kSize; ++i)
        r.add(0.0002); // an in-process link...
    for (size_t i = 0; i < RecentLatency::kSize; ++i)
        r.add(0.002); // ...replaced by a real one: only the recent window counts
    QCOMPARE(r.earliestReplyS(0.0015), 0.0015);
    r.clear();
    QCOMPARE(r.earliestReplyS(0.0015), 0.0);
}

QTEST_APPLESS_MAIN(tst_RecentLatency)
#include "tst_recentlatency.moc"
