// lkctl listen --can on Qt's virtualcan (a TCP port of this test's own): the test is another
// master and its drives on the bus; lkctl prints what they say, pairs requests with replies
// as CAN gives them (0x140+ID shared by the old generation, 0x180+ID for V2.36), and puts
// nothing on the bus: the test's device hears no frame from it.

#include "E2eUtil.h"

#include <QtCore/QProcess>
#include <QtNetwork/QTcpServer>
#include <QtSerialBus/QCanBus>
#include <QtTest/QtTest>

using lk::e2e::jsonOf;

namespace {

quint16 freePort()
{
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0))
        return 0;
    return probe.serverPort();
}

QCanBusFrame frame(quint32 id, const char *hex)
{
    return QCanBusFrame(id, QByteArray::fromHex(hex));
}

} // namespace

class tst_E2eCanListen : public QObject {
    Q_OBJECT
private slots:
    void listensAndSendsNothing()
    {
        const quint16 port = freePort();
        QVERIFY(port != 0);
        const QString url = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
        QString error;
        // This process serves the virtual bus: it outlives lkctl.
        std::unique_ptr<QCanBusDevice> bus(
            QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), url, &error));
        QVERIFY2(bus, qPrintable(error));
        QVERIFY(bus->connectDevice());
        QTRY_COMPARE(bus->state(), QCanBusDevice::ConnectedState);

        QProcess lkctl;
        lkctl.start(QStringLiteral(LKCTL_PATH),
                    {QStringLiteral("listen"), QStringLiteral("--can"),
                     QStringLiteral("virtualcan:") + url, QStringLiteral("--json"),
                     QStringLiteral("--duration"), QStringLiteral("3")});
        QVERIFY(lkctl.waitForStarted());
        // The other master polls until lkctl's --duration is over (lkctl joins the bus at
        // some point of it: the first and last rounds it hears may be partial).
        QElapsedTimer running;
        running.start();
        while (lkctl.state() != QProcess::NotRunning && running.elapsed() < 60000) {
            // Drive 1, old CAN: request and reply on 0x141. Drive 2, V2.36: reply on 0x182.
            bus->writeFrame(frame(0x141, "9C00000000000000"));
            bus->writeFrame(frame(0x141, "9C1E64000A001027"));
            bus->writeFrame(frame(0x142, "9A00000000000000"));
            bus->writeFrame(frame(0x182, "9A1E60090A001000"));
            bus->writeFrame(frame(0x141, "A200000010270000")); // 100.00 dps
            bus->writeFrame(frame(0x141, "A21E64000A001027"));
            QTest::qWait(20); // the virtual bus is served from this event loop
        }
        QVERIFY(lkctl.state() == QProcess::NotRunning || lkctl.waitForFinished(60000));
        const QByteArray out = lkctl.readAllStandardOutput();
        const QByteArray err = lkctl.readAllStandardError();
        QVERIFY2(lkctl.exitCode() == 0, err.constData());
        int speeds = 0, voltages = 0, commanded = 0;
        for (const QByteArray &line : out.split('\n')) {
            if (!line.startsWith('{'))
                continue;
            const QJsonObject o = jsonOf(line);
            if (o.value("id").toInt() == 1 && o.contains("speed_dps")) {
                QCOMPARE(o.value("speed_dps").toDouble(), 10.0);
                ++speeds;
            }
            if (o.value("id").toInt() == 2 && o.contains("voltage_v")) {
                QCOMPARE(o.value("voltage_v").toDouble(), 24.0); // V2.36: 0.01 V
                ++voltages;
            }
            if (o.contains("commanded_speed_dps")) {
                QCOMPARE(o.value("commanded_speed_dps").toDouble(), 100.0);
                ++commanded;
            }
        }
        QVERIFY2(speeds >= 20 && voltages >= 10 && commanded >= 10, err.constData());
        // Every request and reply it heard paired, but for a round cut at either end.
        const QRegularExpression counts(QStringLiteral("requests (\\d+) .*paired (\\d+)"));
        const QRegularExpressionMatch m = counts.match(QString::fromUtf8(err));
        QVERIFY2(m.hasMatch(), err.constData());
        QVERIFY2(m.captured(1).toInt() - m.captured(2).toInt() <= 1, err.constData());
        QVERIFY2(m.captured(2).toInt() >= 30, err.constData());
        QVERIFY2(err.contains("nothing was sent") && err.contains("CAN error frames 0"),
                 err.constData());
        QCOMPARE(bus->framesAvailable(), 0); // lkctl wrote nothing on the bus
    }
};

QTEST_GUILESS_MAIN(tst_E2eCanListen)
#include "tst_e2ecanlisten.moc"
