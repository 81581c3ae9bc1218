#include "E2eUtil.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QTemporaryDir>
#include <QtSerialPort/QSerialPort>
#include <QtTest/QTest>

using namespace lk::e2e;

/// `lkctl off all` (the emergency stop) while another program holds the port: it cannot send,
/// and it must say so plainly - NO drive was stopped - and name the process that holds the
/// port. The other program is this test itself, holding lksim's pty through a QSerialPort
/// (lock file and exclusive open, as lkstudio or a second lkctl would): it holds the port
/// before lkctl starts and until it has ended, so there is no race.
class tst_E2ePortHeld : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanupTestCase();
    void emergencyStopSaysNoDriveWasStopped_data();
    void emergencyStopSaysNoDriveWasStopped();
    void releasedPortStopsTheDrives();

private:
    QStringList port() const { return {QStringLiteral("--port"), m_link}; }

    QTemporaryDir m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

void tst_E2ePortHeld::initTestCase()
{
    m_link = m_dir.filePath(QStringLiteral("bus"));
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    QVERIFY2(m_sim->start(simArgs(m_link)), qPrintable(m_sim->errorString()));
}

void tst_E2ePortHeld::cleanupTestCase()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
}

void tst_E2ePortHeld::emergencyStopSaysNoDriveWasStopped_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("halt");
    QTest::newRow("off all") << "off"
                             << "motor_off";
    QTest::newRow("stop all") << "stop"
                              << "motor_stop";
}

void tst_E2ePortHeld::emergencyStopSaysNoDriveWasStopped()
{
    QFETCH(QString, command);
    QFETCH(QString, halt);
    const std::optional<LksimCounters> before = m_sim->currentCounters();
    QVERIFY(before);
    QSerialPort holder(m_link);
    QVERIFY2(holder.open(QIODevice::ReadWrite), qPrintable(holder.errorString()));

    const CtlResult r = lkctl(QStringList{command, QStringLiteral("all")} + port());
    holder.close();

    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.out, QByteArray());
    const QString err = QString::fromUtf8(r.err);
    QVERIFY2(err.contains(QLatin1String("in use by another program")), qPrintable(err));
    // This process, named as the system names it.
    const QString me = QStringLiteral("%1 (%2)")
                           .arg(QCoreApplication::applicationPid())
                           .arg(QFileInfo(QCoreApplication::arguments().first()).fileName());
    QVERIFY2(err.contains(QStringLiteral("is held open by")), qPrintable(err));
    QVERIFY2(err.contains(me), qPrintable(QStringLiteral("%1 not named in:\n%2").arg(me, err)));
    QVERIFY2(err.contains(QStringLiteral("NO drive was stopped: nothing was sent (%1)").arg(halt)),
             qPrintable(err));
    // And indeed nothing reached the bus.
    const std::optional<LksimCounters> after = m_sim->currentCounters();
    QVERIFY(after);
    QCOMPARE(after->requests, before->requests);
}

void tst_E2ePortHeld::releasedPortStopsTheDrives()
{
    const CtlResult r =
        lkctl(QStringList{QStringLiteral("off"), QStringLiteral("all"), QStringLiteral("--json")} +
              port());
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(jsonOf(r.out).value(QStringLiteral("acknowledged")).toArray().size(), 3);
    QVERIFY2(!r.err.contains("NO drive was stopped"), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_E2ePortHeld)
#include "tst_e2eportheld.moc"
