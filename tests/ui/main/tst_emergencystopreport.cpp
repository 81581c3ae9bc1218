// The emergency stop's banner report, case by case: what was acknowledged, what never went
// out, who may still be moving, what has come back while the stop is under way, and a stop
// pressed while disconnected that went out on reconnect.

#include <main/EmergencyStopReport.h>

#include <QtTest/QtTest>

using lk::ui::EmergencyStopReport;
using lk::ui::MessageBanner;
using Level = MessageBanner::Level;

namespace {
QVector<int> range(int first, int last)
{
    QVector<int> ids;
    for (int id = first; id <= last; ++id)
        ids << id;
    return ids;
}

EmergencyStopReport::Context context(const QVector<int> &watched, const QStringList &commanded = {})
{
    EmergencyStopReport::Context c;
    c.watched = watched;
    c.commanded = commanded;
    return c;
}

EmergencyStopReport::Outcome outcome(const QVector<int> &acknowledged, const QVector<int> &silent,
                                     const QVector<int> &unsent = {})
{
    EmergencyStopReport::Outcome o;
    o.acknowledged = acknowledged;
    o.silent = silent;
    o.unsent = unsent;
    return o;
}
} // namespace

class tst_EmergencyStopReport : public QObject {
    Q_OBJECT
private slots:
    void everyDriveAcknowledged();
    void watchedDriveSilent();
    void linkDroppedHalfway();
    void nothingSent_data();
    void nothingSent();
    void underWayFillsIn();
    void sinceStoppedLeavesTheRed();
    void sentOnReconnectSaysSo();
};

void tst_EmergencyStopReport::everyDriveAcknowledged()
{
    const auto t = EmergencyStopReport::compose(context({1, 2}), outcome({1, 2}, range(3, 32)));
    QCOMPARE(t.level, Level::Info);
    QVERIFY2(t.html.contains(QStringLiteral("sent to 32 ID(s); acknowledged by drive(s) 1, 2.")),
             qPrintable(t.html));
    QVERIFY(!t.html.contains(QStringLiteral("NO answer")));
    QVERIFY(!t.html.contains(QStringLiteral("NEVER")));
}

void tst_EmergencyStopReport::watchedDriveSilent()
{
    const auto t = EmergencyStopReport::compose(context({1, 2}), outcome({1}, range(2, 32)));
    QCOMPARE(t.level, Level::Error);
    QVERIFY2(t.html.contains(QStringLiteral("NO answer from drive(s) 2:")), qPrintable(t.html));
    QVERIFY(!t.html.contains(QStringLiteral("NEVER")));
}

void tst_EmergencyStopReport::linkDroppedHalfway()
{
    // Drive 1 answered; the link dropped before the halt went out to 2 and to 20..32. Drive
    // 2 was watched: it is named as never reached, not as "no answer".
    QVector<int> unsent{2};
    unsent += range(20, 32);
    const auto t =
        EmergencyStopReport::compose(context({1, 2, 3}), outcome({1}, range(2, 32), unsent));
    QCOMPARE(t.level, Level::Error);
    QVERIFY2(t.html.contains(QStringLiteral("sent to 18 ID(s)")), qPrintable(t.html));
    QVERIFY(t.html.contains(QStringLiteral("14 of 32 could not be sent")));
    QVERIFY2(t.html.contains(QStringLiteral("Motor Off NEVER reached drive(s) 2:")),
             qPrintable(t.html));
    QVERIFY2(t.html.contains(QStringLiteral("NO answer from drive(s) 3:")), qPrintable(t.html));
}

void tst_EmergencyStopReport::nothingSent_data()
{
    QTest::addColumn<QStringList>("commanded");
    QTest::addColumn<QString>("expected");
    QTest::newRow("nothing commanded") << QStringList{} << "has not commanded any drive";
    QTest::newRow("drive 2 commanded") << QStringList{QStringLiteral("Drive 2 (speed 360 dps)")}
                                       << "Last commanded to move: Drive 2 (speed 360 dps).";
}

void tst_EmergencyStopReport::nothingSent()
{
    QFETCH(QStringList, commanded);
    QFETCH(QString, expected);
    const auto t = EmergencyStopReport::compose(context({2}, commanded),
                                                outcome({}, range(1, 32), range(1, 32)));
    QCOMPARE(t.level, Level::Error);
    QVERIFY(t.html.contains(QStringLiteral("NOTHING could be sent")));
    QVERIFY2(t.html.contains(expected), qPrintable(t.html));
}

void tst_EmergencyStopReport::underWayFillsIn()
{
    // Shown at once: before any result, and as the acknowledgements come.
    EmergencyStopReport::Outcome o;
    o.remaining = 32;
    auto t = EmergencyStopReport::compose(context({9, 20}), o);
    QCOMPARE(t.level, Level::Warning);
    QVERIFY2(t.html.contains(QStringLiteral("going out to every ID 1-32 (0 of 32 done)")),
             qPrintable(t.html));
    QVERIFY2(t.html.contains(QStringLiteral("Waiting for drive(s) 9, 20.")), qPrintable(t.html));
    o = outcome({20}, {1});
    o.remaining = 30;
    t = EmergencyStopReport::compose(context({9, 20}), o);
    QVERIFY2(t.html.contains(QStringLiteral("(2 of 32 done)")), qPrintable(t.html));
    QVERIFY2(t.html.contains(QStringLiteral("Acknowledged so far by drive(s) 20.")),
             qPrintable(t.html));
    QVERIFY2(t.html.contains(QStringLiteral("Waiting for drive(s) 9.")), qPrintable(t.html));
    QVERIFY(!t.html.contains(QStringLiteral("NO answer")));
}

void tst_EmergencyStopReport::sinceStoppedLeavesTheRed()
{
    const auto ctx = context({1, 2, 3});
    EmergencyStopReport::Outcome o = outcome({1}, range(2, 32));
    QCOMPARE(EmergencyStopReport::mayBeMoving(ctx, o), (QVector<int>{2, 3}));
    o.sinceStopped = {2};
    auto t = EmergencyStopReport::compose(ctx, o);
    QCOMPARE(t.level, Level::Error); // drive 3 still unaccounted for
    QVERIFY2(t.html.contains(QStringLiteral("NO answer from drive(s) 3:")), qPrintable(t.html));
    QVERIFY2(t.html.contains(QStringLiteral("Drive(s) 2 did not answer but have since read "
                                            "stopped.")),
             qPrintable(t.html));
    QCOMPARE(EmergencyStopReport::mayBeMoving(ctx, o), QVector<int>{3});
    o.sinceStopped = {2, 3};
    t = EmergencyStopReport::compose(ctx, o);
    QCOMPARE(t.level, Level::Info);
    QVERIFY(!t.html.contains(QStringLiteral("NO answer")));
    QVERIFY(EmergencyStopReport::mayBeMoving(ctx, o).isEmpty());
}

void tst_EmergencyStopReport::sentOnReconnectSaysSo()
{
    auto ctx = context({2}, {QStringLiteral("Drive 2 (speed 360 dps)")});
    // Nothing could be sent: the operator hears that it goes out once the port is back.
    auto t = EmergencyStopReport::compose(ctx, outcome({}, range(1, 32), range(1, 32)));
    QVERIFY2(t.html.contains(QStringLiteral("as soon as this port is connected again")),
             qPrintable(t.html));
    QCOMPARE(EmergencyStopReport::mayBeMoving(ctx, outcome({}, range(1, 32), range(1, 32))),
             QVector<int>{2});
    ctx.pressedWhileDisconnectedAt = QStringLiteral("12:03:04");
    t = EmergencyStopReport::compose(ctx, outcome({2}, range(3, 32) + QVector<int>{1}));
    QCOMPARE(t.level, Level::Info);
    QVERIFY2(t.html.contains(QStringLiteral("Pressed at 12:03:04 while the bus was not "
                                            "connected; sent as soon as it was back.")),
             qPrintable(t.html));
    QVERIFY(t.html.contains(QStringLiteral("acknowledged by drive(s) 2.")));
}

QTEST_MAIN(tst_EmergencyStopReport)
#include "tst_emergencystopreport.moc"
