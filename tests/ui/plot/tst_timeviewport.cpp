#include <plot/TimeViewport.h>

#include <QtTest/QTest>

using lk::ui::TimeSpan;
using lk::ui::TimeViewport;

Q_DECLARE_METATYPE(TimeSpan)

class tst_TimeViewport : public QObject {
    Q_OBJECT
private slots:
    void followsLatest_data();
    void followsLatest();
    void zoomKeepsAnchor_data();
    void zoomKeepsAnchor();
    void panAndSelectStopFollowing();
    void windowChangeWhileFixedKeepsRightEdge();
    void spanIsClamped();
};

void tst_TimeViewport::followsLatest_data()
{
    QTest::addColumn<double>("window");
    QTest::addColumn<double>("latest");
    QTest::addColumn<double>("begin");
    QTest::addColumn<double>("end");
    QTest::newRow("before a window is recorded") << 10.0 << 3.0 << 0.0 << 10.0;
    QTest::newRow("exactly one window") << 10.0 << 10.0 << 0.0 << 10.0;
    QTest::newRow("later") << 10.0 << 42.5 << 32.5 << 42.5;
    QTest::newRow("5 min") << 300.0 << 1000.0 << 700.0 << 1000.0;
}

void tst_TimeViewport::followsLatest()
{
    QFETCH(double, window);
    QFETCH(double, latest);
    QFETCH(double, begin);
    QFETCH(double, end);
    TimeViewport v;
    v.setWindow(window);
    QVERIFY(v.isFollowing());
    const TimeSpan r = v.range(latest);
    QCOMPARE(r.begin, begin);
    QCOMPARE(r.end, end);
}

void tst_TimeViewport::zoomKeepsAnchor_data()
{
    QTest::addColumn<double>("factor");
    QTest::addColumn<double>("anchor");
    QTest::newRow("in at the middle") << 0.5 << 25.0;
    QTest::newRow("in at the left edge") << 0.8 << 20.0;
    QTest::newRow("out near the right") << 2.0 << 29.0;
}

void tst_TimeViewport::zoomKeepsAnchor()
{
    QFETCH(double, factor);
    QFETCH(double, anchor);
    TimeViewport v; // follows with 10 s: at latest 30 shows 20 .. 30
    const TimeSpan before = v.range(30);
    const double share = (anchor - before.begin) / before.length();
    v.zoom(factor, anchor, 30);
    QVERIFY(!v.isFollowing());
    const TimeSpan after = v.range(1000); // no longer follows: latest is ignored
    QCOMPARE(after.length(), before.length() * factor);
    QCOMPARE((anchor - after.begin) / after.length(), share);
}

void tst_TimeViewport::panAndSelectStopFollowing()
{
    TimeViewport v;
    v.pan(-3, 30);
    QVERIFY(!v.isFollowing());
    QCOMPARE(v.range(99).begin, 17.0);
    QCOMPARE(v.range(99).end, 27.0);
    v.select(12, 4);
    QCOMPARE(v.range(99).begin, 4.0);
    QCOMPARE(v.range(99).end, 12.0);
    v.follow();
    QVERIFY(v.isFollowing());
    QCOMPARE(v.range(99).end, 99.0);
}

void tst_TimeViewport::windowChangeWhileFixedKeepsRightEdge()
{
    TimeViewport v;
    v.select(50, 60);
    v.setWindow(30);
    QCOMPARE(v.range(0).begin, 30.0);
    QCOMPARE(v.range(0).end, 60.0);
    QVERIFY(!v.isFollowing());
}

void tst_TimeViewport::spanIsClamped()
{
    TimeViewport v;
    v.select(1, 1); // zero width would divide by zero in the charts
    QVERIFY(v.range(0).length() >= TimeViewport::kMinSpan * (1 - 1e-9));
    v.zoom(1e12, 0, 0);
    QVERIFY(v.range(0).length() <= TimeViewport::kMaxSpan);
}

QTEST_APPLESS_MAIN(tst_TimeViewport)
#include "tst_timeviewport.moc"
