#include <system/LocalTimeZone.h>

#include <QtCore/QDateTime>
#include <QtCore/QFileInfo>
#include <QtTest/QTest>

#include <ctime>

using lk::system::LocalTimeZone;

/// The time zone is read once per process: TZ names /etc/localtime unless the user set it.
class tst_LocalTimeZone : public QObject {
    Q_OBJECT
private slots:
    void unsetNamesTheSystemZone();
    void userSettingIsKept();
};

void tst_LocalTimeZone::unsetNamesTheSystemZone()
{
    qunsetenv("TZ");
    tzset();
    const QDateTime noon(QDate(2026, 7, 1), QTime(12, 0));
    const int offsetBefore = noon.offsetFromUtc();
    LocalTimeZone::readOnce();
    if (!QFileInfo::exists(QStringLiteral("/etc/localtime"))) {
        QVERIFY(!qEnvironmentVariableIsSet("TZ")); // nothing to name: glibc's UTC stays
        return;
    }
    QCOMPARE(qgetenv("TZ"), QByteArray(":/etc/localtime"));
    tzset();
    // The same zone as before, only read once: local times do not move.
    QCOMPARE(QDateTime(QDate(2026, 7, 1), QTime(12, 0)).offsetFromUtc(), offsetBefore);
}

void tst_LocalTimeZone::userSettingIsKept()
{
    qputenv("TZ", "Asia/Shanghai");
    LocalTimeZone::readOnce();
    QCOMPARE(qgetenv("TZ"), QByteArray("Asia/Shanghai"));
    qputenv("TZ", "");
    LocalTimeZone::readOnce();
    QCOMPARE(qgetenv("TZ"), QByteArray()); // set, if empty (glibc's UTC): still the user's
    QVERIFY(qEnvironmentVariableIsSet("TZ"));
}

QTEST_APPLESS_MAIN(tst_LocalTimeZone)
#include "tst_localtimezone.moc"
