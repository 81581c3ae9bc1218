// The emergency stop's banner report, case by case: what was acknowledged, what never went
// out, and who may still be moving.

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
} // namespace

class tst_EmergencyStopReport : public QObject {
    Q_OBJECT
private slots:
    void everyDriveAcknowledged();
    void watchedDriveSilent();
    void linkDroppedHalfway();
    void nothingSent_data();
    void nothingSent();
};

void tst_EmergencyStopReport::everyDriveAcknowledged()
{
    const auto t = EmergencyStopReport::compose({{1, 2}, {}}, {{1, 2}, range(3, 32), {}});
    QCOMPARE(t.level, Level::Info);
    QVERIFY2(t.html.contains(QStringLiteral("sent to 32 ID(s); acknowledged by drive(s) 1, 2.")),
             qPrintable(t.html));
    QVERIFY(!t.html.contains(QStringLiteral("NO answer")));
    QVERIFY(!t.html.contains(QStringLiteral("NEVER")));
}

void tst_EmergencyStopReport::watchedDriveSilent()
{
    const auto t = EmergencyStopReport::compose({{1, 2}, {}}, {{1}, range(2, 32), {}});
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
    const auto t = EmergencyStopReport::compose({{1, 2, 3}, {}}, {{1}, range(2, 32), unsent});
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
    const auto t = EmergencyStopReport::compose({{2}, commanded}, {{}, range(1, 32), range(1, 32)});
    QCOMPARE(t.level, Level::Error);
    QVERIFY(t.html.contains(QStringLiteral("NOTHING could be sent")));
    QVERIFY2(t.html.contains(expected), qPrintable(t.html));
}

QTEST_MAIN(tst_EmergencyStopReport)
#include "tst_emergencystopreport.moc"
