// DiagnosticsReport: the text of Help > Copy diagnostics carries the versions, the port and
// its adapter's VID:PID, the bus statistics and the latest errors from the log.

#include <main/DiagnosticsReport.h>
#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>
#include <system/LogFile.h>

#include <QtCore/QLoggingCategory>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::ui::DiagnosticsReport;
using lk::ui::PortEntry;

namespace {
Q_LOGGING_CATEGORY(lcTest, "lk.test")

PortEntry ftdi()
{
    PortEntry p;
    p.name = QStringLiteral("ttyUSB0");
    p.location = QStringLiteral("/dev/ttyUSB0");
    p.description = QStringLiteral("FT232R USB UART");
    p.manufacturer = QStringLiteral("FTDI");
    p.vendorId = 0x0403;
    p.productId = 0x6001;
    return p;
}

lk::bus::BusStatistics statistics()
{
    lk::bus::BusStatistics s;
    s.time = 12.5;
    s.baud = 115200;
    s.bus.requests = 1000;
    s.bus.replies = 990;
    s.bus.timeouts = 7;
    s.bus.checksumErrors = 3;
    s.bus.garbageBytes = 42;
    s.bus.latency.samples = 990;
    s.bus.latency.medianMs = 1.9;
    s.bus.latency.p95Ms = 2.4;
    s.bus.latency.maxMs = 9.75;
    lk::bus::LinkStatistics one;
    one.requests = 600;
    one.replies = 597;
    one.timeouts = 3;
    s.perId.insert(1, one);
    return s;
}

lk::ui::ConnectionChoice serial(const QString &port)
{
    lk::ui::ConnectionChoice c;
    c.kind = lk::ui::ConnectionChoice::Kind::Serial;
    c.port = port;
    return c;
}
} // namespace

class tst_DiagnosticsReport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7")); }
    void versionsAreNamed();
    void serialLinkWithAdapter();
    void adapterFor_data();
    void adapterFor();
    void unlistedAdapterIsSaid();
    void simulatorHasNoAdapterLine();
    void noTrafficSaysSo();
    void recentErrorsComeFromTheLog();
};

void tst_DiagnosticsReport::versionsAreNamed()
{
    const QString text = DiagnosticsReport::text(DiagnosticsReport::systemInfo());
    QVERIFY2(text.contains(QStringLiteral("lkstudio 9.8.7")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("Qt:            %1 (built with %2), platform %3")
                              .arg(QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR),
                                   QGuiApplication::platformName())));
    QVERIFY(text.contains(QSysInfo::prettyProductName()));
    QVERIFY(text.contains(QSysInfo::kernelVersion()));
}

void tst_DiagnosticsReport::serialLinkWithAdapter()
{
    lk::ui::BusModel model;
    lk::bus::ConnectionStatus status;
    status.state = lk::transport::Transport::State::Open;
    status.description = QStringLiteral("/dev/ttyUSB0 @ 115200");
    status.baud = 115200;
    model.setConnection(status, false);
    model.setStatistics(statistics());
    const QString text = DiagnosticsReport::text(
        DiagnosticsReport::gather(model, serial(QStringLiteral("/dev/ttyUSB0")), {ftdi()}));
    QVERIFY2(
        text.contains(QStringLiteral("serial port /dev/ttyUSB0, open (/dev/ttyUSB0 @ 115200)")),
        qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("Adapter:       0403:6001 FT232R USB UART, FTDI")));
    QVERIFY(text.contains(QStringLiteral("12.5 s at 115200 baud")));
    QVERIFY(text.contains(QStringLiteral("requests 1000, replies 990, timeouts 7")));
    QVERIFY(text.contains(QStringLiteral("checksum errors 3")));
    QVERIFY(text.contains(QStringLiteral("garbage bytes 42")));
    QVERIFY(text.contains(QStringLiteral("median 1.90 ms, p95 2.40 ms, max 9.75 ms")));
    QVERIFY(text.contains(QStringLiteral("ID 1:        requests 600, replies 597, timeouts 3")));
}

void tst_DiagnosticsReport::adapterFor_data()
{
    QTest::addColumn<QString>("port");
    QTest::addColumn<bool>("found");
    QTest::newRow("device path") << QStringLiteral("/dev/ttyUSB0") << true;
    QTest::newRow("name only") << QStringLiteral("ttyUSB0") << true;
    QTest::newRow("other port") << QStringLiteral("/dev/ttyUSB1") << false;
    QTest::newRow("prefix is not a match") << QStringLiteral("/dev/ttyUSB00") << false;
    QTest::newRow("empty") << QString() << false;
}

void tst_DiagnosticsReport::adapterFor()
{
    QFETCH(QString, port);
    QFETCH(bool, found);
    QCOMPARE(DiagnosticsReport::adapterFor(port, {ftdi()}).has_value(), found);
}

void tst_DiagnosticsReport::unlistedAdapterIsSaid()
{
    lk::ui::BusModel model;
    const QString text = DiagnosticsReport::text(
        DiagnosticsReport::gather(model, serial(QStringLiteral("/dev/pts/7")), {ftdi()}));
    QVERIFY2(text.contains(QStringLiteral("Adapter:       not listed")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("serial port /dev/pts/7, closed")));
}

void tst_DiagnosticsReport::simulatorHasNoAdapterLine()
{
    lk::ui::BusModel model;
    const QString text =
        DiagnosticsReport::text(DiagnosticsReport::gather(model, lk::ui::ConnectionChoice{}, {}));
    QVERIFY2(text.contains(QStringLiteral("built-in simulator")), qPrintable(text));
    QVERIFY(!text.contains(QStringLiteral("Adapter:")));
}

void tst_DiagnosticsReport::noTrafficSaysSo()
{
    lk::ui::BusModel model;
    const QString text =
        DiagnosticsReport::text(DiagnosticsReport::gather(model, lk::ui::ConnectionChoice{}, {}));
    QVERIFY2(text.contains(QStringLiteral("Statistics:    no traffic yet")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("Drives:        none found")));
}

void tst_DiagnosticsReport::recentErrorsComeFromTheLog()
{
    QTemporaryDir dir;
    lk::system::LogFile log(dir.filePath(QStringLiteral("lkstudio.log")));
    QVERIFY(log.open());
    log.install();
    qCWarning(lcTest) << "Cannot use /dev/ttyUSB0: permission denied";
    qCInfo(lcTest) << "Connected";
    lk::ui::BusModel model;
    const QString text =
        DiagnosticsReport::text(DiagnosticsReport::gather(model, lk::ui::ConnectionChoice{}, {}));
    log.uninstall();
    QVERIFY2(text.contains(QStringLiteral("Cannot use /dev/ttyUSB0: permission denied")),
             qPrintable(text));
    QVERIFY(!text.contains(QStringLiteral("Connected")));
    QVERIFY(text.contains(QStringLiteral("Log file:      ") + log.path()));
}

QTEST_MAIN(tst_DiagnosticsReport)
#include "tst_diagnosticsreport.moc"
