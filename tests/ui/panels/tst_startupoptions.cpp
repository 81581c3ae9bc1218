#include <main/AppSettings.h>
#include <main/StartupOptions.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::ui::AppSettings;
using lk::ui::ConnectionChoice;
using lk::ui::StartupOptions;

namespace {

/// Parse `args` (without the program name) into `out`: true when it was refused exactly when
/// `refusal` is not empty, with a message that contains it.
bool parsedAsExpected(QStringList args, const QString &refusal, std::optional<StartupOptions> *out)
{
    args.prepend(QStringLiteral("lkstudio"));
    QString error;
    *out = StartupOptions::parse(args, &error);
    if (out->has_value() != refusal.isEmpty() || (!*out && !error.contains(refusal))) {
        qWarning("%s", qPrintable(error));
        return false;
    }
    return true;
}

} // namespace

class tst_StartupOptions : public QObject {
    Q_OBJECT
private slots:
    void parse_data();
    void parse();
    void display_data();
    void display();
    void initialChoice_data();
    void initialChoice();
    void listenOnly_data();
    void listenOnly();
    void can_data();
    void can();
    void rememberedCan_data();
    void rememberedCan();
    void simulatedCan_data();
    void simulatedCan();

private:
    QTemporaryDir m_dir;
};

void tst_StartupOptions::parse_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<QString>("port");
    QTest::addColumn<int>("baud");
    QTest::addColumn<int>("simDrives");
    QTest::newRow("none") << QStringList{} << true << QString() << 115200 << 0;
    QTest::newRow("port and baud") << QStringList{"--port", "/dev/ttyUSB0", "--baud", "1000000"}
                                   << true << "/dev/ttyUSB0" << 1000000 << 0;
    QTest::newRow("sim") << QStringList{"--sim", "1:MF,2:MG,3:MS"} << true << QString() << 115200
                         << 3;
    QTest::newRow("sim motor name")
        << QStringList{"--sim", "5:MG5010E-i36"} << true << QString() << 115200 << 1;
    QTest::newRow("bad baud") << QStringList{"--baud", "12345"} << false << QString() << 0 << 0;
    QTest::newRow("text baud") << QStringList{"--baud", "fast"} << false << QString() << 0 << 0;
    QTest::newRow("bad sim id") << QStringList{"--sim", "40:MF"} << false << QString() << 0 << 0;
    QTest::newRow("bad sim series") << QStringList{"--sim", "1:XX"} << false << QString() << 0 << 0;
    QTest::newRow("port and sim") << QStringList{"--port", "COM3", "--sim", "1:MF"} << false
                                  << QString() << 0 << 0;
    QTest::newRow("stray argument") << QStringList{"ttyUSB0"} << false << QString() << 0 << 0;
    // A file is a recording to replay (here any file that exists: this test's binary).
    QTest::newRow("recording") << QStringList{QCoreApplication::applicationFilePath()} << true
                               << QString() << 115200 << 0;
    QTest::newRow("two recordings") << QStringList{QCoreApplication::applicationFilePath(),
                                                   QCoreApplication::applicationFilePath()}
                                    << false << QString() << 0 << 0;
    QTest::newRow("unknown option") << QStringList{"--frobnicate"} << false << QString() << 0 << 0;
    QTest::newRow("select 33") << QStringList{"--select", "33"} << false << QString() << 0 << 0;
    QTest::newRow("sim faults") << QStringList{"--sim-faults", "corrupt=0.01,garbage=0.02"} << true
                                << QString() << 115200 << 0;
    QTest::newRow("bad sim faults")
        << QStringList{"--sim-faults", "corrupt=2"} << false << QString() << 0 << 0;
    QTest::newRow("sim faults on a port")
        << QStringList{"--port", "/dev/ttyUSB0", "--sim-faults", "drop=0.1"} << false << QString()
        << 0 << 0;
    QTest::newRow("negative delay")
        << QStringList{"--screenshot-delay-ms", "-1"} << false << QString() << 0 << 0;
}

void tst_StartupOptions::parse()
{
    QFETCH(QStringList, args);
    QFETCH(bool, ok);
    QFETCH(QString, port);
    QFETCH(int, baud);
    QFETCH(int, simDrives);
    args.prepend(QStringLiteral("lkstudio"));
    QString error;
    const auto o = StartupOptions::parse(args, &error);
    QCOMPARE(o.has_value(), ok);
    if (!ok) {
        QVERIFY2(!error.isEmpty(), "a refusal says why");
        return;
    }
    QCOMPARE(o->port.value_or(QString()), port);
    QCOMPARE(o->baud, baud);
    QCOMPARE(o->sim ? int(o->sim->drives.size()) : 0, simDrives);
}

void tst_StartupOptions::display_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("palette");
    QTest::addColumn<int>("cycleViewsMs");
    QTest::newRow("defaults") << QStringList{} << true << QString() << QString() << 0;
    QTest::newRow("chinese") << QStringList{"--language", "zh_CN"} << true << "zh_CN" << QString()
                             << 0;
    QTest::newRow("dark") << QStringList{"--palette", "dark"} << true << QString() << "dark" << 0;
    QTest::newRow("light") << QStringList{"--palette", "light"} << true << QString() << "light"
                           << 0;
    QTest::newRow("bad palette") << QStringList{"--palette", "purple"} << false << QString()
                                 << QString() << 0;
    QTest::newRow("cycle views") << QStringList{"--cycle-views", "1000"} << true << QString()
                                 << QString() << 1000;
    QTest::newRow("cycle views too fast")
        << QStringList{"--cycle-views", "10"} << false << QString() << QString() << 0;
    QTest::newRow("cycle views text")
        << QStringList{"--cycle-views", "often"} << false << QString() << QString() << 0;
}

void tst_StartupOptions::display()
{
    QFETCH(QStringList, args);
    QFETCH(bool, ok);
    QFETCH(QString, language);
    QFETCH(QString, palette);
    QFETCH(int, cycleViewsMs);
    QString error;
    const auto o = lk::ui::StartupOptions::parse(QStringList{"lkstudio"} + args, &error);
    QCOMPARE(o.has_value(), ok);
    QCOMPARE(error.isEmpty(), ok);
    if (!o)
        return;
    QCOMPARE(o->language, language);
    QCOMPARE(o->palette, palette);
    QCOMPARE(o->cycleViewsMs, cycleViewsMs);
}

void tst_StartupOptions::initialChoice_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("rememberedSerial");
    QTest::addColumn<bool>("portPlugged");
    QTest::addColumn<bool>("expectSimulator");
    QTest::addColumn<QString>("expectPort");
    QTest::addColumn<bool>("fellBack");
    QTest::newRow("first run") << QStringList{} << false << false << true << QString() << false;
    QTest::newRow("remembered port present")
        << QStringList{} << true << true << false << "/dev/ttyUSB3" << false;
    QTest::newRow("remembered port away")
        << QStringList{} << true << false << true << "/dev/ttyUSB3" << true;
    QTest::newRow("--port wins") << QStringList{"--port", "/dev/pts/4"} << false << false << false
                                 << "/dev/pts/4" << false;
    QTest::newRow("--sim wins") << QStringList{"--sim", "1:MF"} << true << true << true
                                << "/dev/ttyUSB3" << false;
}

void tst_StartupOptions::initialChoice()
{
    QFETCH(QStringList, args);
    QFETCH(bool, rememberedSerial);
    QFETCH(bool, portPlugged);
    QFETCH(bool, expectSimulator);
    QFETCH(QString, expectPort);
    QFETCH(bool, fellBack);
    const QString file = m_dir.filePath(QString::fromLatin1(QTest::currentDataTag()) + ".ini");
    AppSettings settings(file);
    if (rememberedSerial) {
        ConnectionChoice c;
        c.kind = ConnectionChoice::Kind::Serial;
        c.port = QStringLiteral("/dev/ttyUSB3");
        settings.setConnection(c);
    }
    args.prepend(QStringLiteral("lkstudio"));
    const auto o = StartupOptions::parse(args, nullptr);
    QVERIFY(o);
    const auto exists = [portPlugged](const QString &) { return portPlugged; };
    const ConnectionChoice c = o->initialChoice(settings, exists);
    QCOMPARE(c.isSimulator(), expectSimulator);
    QCOMPARE(c.port, expectPort);
    QCOMPARE(o->fellBackToSimulator(settings, exists), fellBack);
}

void tst_StartupOptions::listenOnly_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("rememberedListening"); // on /dev/ttyUSB3
    QTest::addColumn<bool>("portPlugged");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<bool>("expectListen");
    QTest::newRow("as last time") << QStringList{} << true << true << true << true;
    QTest::newRow("--listen") << QStringList{"--listen"} << false << true << true << true;
    QTest::newRow("--no-listen") << QStringList{"--no-listen"} << true << true << true << false;
    QTest::newRow("both") << QStringList{"--listen", "--no-listen"} << false << true << false
                          << false;
    // The built-in bus has no other master: a fallback to it is its master.
    QTest::newRow("port away") << QStringList{} << true << false << true << false;
    QTest::newRow("--listen --sim")
        << QStringList{"--listen", "--sim", "1:MF"} << false << false << true << true;
}

void tst_StartupOptions::listenOnly()
{
    QFETCH(QStringList, args);
    QFETCH(bool, rememberedListening);
    QFETCH(bool, portPlugged);
    QFETCH(bool, ok);
    QFETCH(bool, expectListen);
    const QString file =
        m_dir.filePath(QStringLiteral("listen-%1.ini").arg(QTest::currentDataTag()));
    AppSettings settings(file);
    ConnectionChoice remembered;
    remembered.kind = ConnectionChoice::Kind::Serial;
    remembered.port = QStringLiteral("/dev/ttyUSB3");
    remembered.listenOnly = rememberedListening;
    settings.setConnection(remembered);
    QString error;
    const auto o = StartupOptions::parse(QStringList{"lkstudio"} + args, &error);
    QCOMPARE(o.has_value(), ok);
    if (!o) {
        QVERIFY(error.contains(QStringLiteral("--listen")));
        return;
    }
    const auto exists = [portPlugged](const QString &) { return portPlugged; };
    QCOMPARE(o->initialChoice(settings, exists).listenOnly, expectListen);
}

void tst_StartupOptions::can_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("refusal"); ///< empty: accepted
    QTest::addColumn<QString>("plugin");
    QTest::addColumn<QString>("iface");
    QTest::addColumn<int>("bitRate");
    QTest::newRow("socketcan") << QStringList{"--can", "socketcan:can0"} << QString() << "socketcan"
                               << "can0" << 1000000;
    QTest::newRow("bit rate") << QStringList{"--can", "socketcan:slcan0", "--bitrate", "500000"}
                              << QString() << "socketcan"
                              << "slcan0" << 500000;
    QTest::newRow("virtualcan url") << QStringList{"--can", "virtualcan:tcp://127.0.0.1:35468/can1"}
                                    << QString() << "virtualcan"
                                    << "tcp://127.0.0.1:35468/can1" << 1000000;
    QTest::newRow("no interface") << QStringList{"--can", "socketcan"} << "--can takes PLUGIN"
                                  << QString() << QString() << 0;
    QTest::newRow("odd bit rate") << QStringList{"--can", "socketcan:can0", "--bitrate", "800000"}
                                  << "--bitrate 800000 is not" << QString() << QString() << 0;
    QTest::newRow("with port") << QStringList{"--can", "socketcan:can0", "--port", "/dev/ttyUSB0"}
                               << "exclude each other" << QString() << QString() << 0;
    QTest::newRow("bit rate on rs485")
        << QStringList{"--port", "/dev/ttyUSB0", "--bitrate", "500000"} << "--bitrate is the bit"
        << QString() << QString() << 0;
}

void tst_StartupOptions::can()
{
    QFETCH(QStringList, args);
    QFETCH(QString, refusal);
    QFETCH(QString, plugin);
    QFETCH(QString, iface);
    QFETCH(int, bitRate);
    std::optional<StartupOptions> o;
    QVERIFY(parsedAsExpected(args, refusal, &o));
    if (!o)
        return;
    AppSettings settings(m_dir.filePath(QString::fromLatin1(QTest::currentDataTag()) + ".ini"));
    const auto absent = [](const QString &) { return false; };
    const ConnectionChoice c = o->initialChoice(settings, absent);
    QVERIFY(c.isCan()); // asked for: opened even when not listed (it says why if it fails)
    QCOMPARE(c.canPlugin, plugin);
    QCOMPARE(c.canInterface, iface);
    QCOMPARE(c.bitRate, bitRate);
    QVERIFY(!o->fellBackToSimulator(settings, absent));
}

void tst_StartupOptions::rememberedCan_data()
{
    QTest::addColumn<bool>("present");
    QTest::newRow("interface up") << true;
    QTest::newRow("interface away") << false;
}

void tst_StartupOptions::rememberedCan()
{
    // The last connection was CAN: opened again when its interface is there, else the
    // simulated bus (and the CAN choice stays remembered).
    QFETCH(bool, present);
    AppSettings settings(m_dir.filePath(QString::fromLatin1(QTest::currentDataTag()) + ".ini"));
    ConnectionChoice remembered;
    remembered.kind = ConnectionChoice::Kind::Can;
    remembered.canInterface = QStringLiteral("can3");
    remembered.bitRate = 250000;
    settings.setConnection(remembered);
    QStringList asked;
    const auto exists = [&](const QString &port) {
        asked << port;
        return present;
    };
    const auto o = StartupOptions::parse({QStringLiteral("lkstudio")}, nullptr);
    QVERIFY(o);
    const ConnectionChoice c = o->initialChoice(settings, exists);
    QCOMPARE(asked.value(0), QStringLiteral("can:socketcan:can3"));
    QCOMPARE(c.isCan(), present);
    QCOMPARE(o->fellBackToSimulator(settings, exists), !present);
    if (present)
        QCOMPARE(c, remembered);
    else // without the adapter the drives are simulated on the same link
        QVERIFY(c.isSimulator() && c.simulatedCan && c.link() == lk::protocol::Link::Can);
}

void tst_StartupOptions::simulatedCan_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("refusal"); ///< empty: accepted
    QTest::addColumn<int>("simDrives");   ///< 0: the default drives
    QTest::addColumn<int>("bitRate");
    QTest::newRow("can sim") << QStringList{"--can", "sim"} << QString() << 0 << 1000000;
    QTest::newRow("with drives and bit rate")
        << QStringList{"--can", "sim", "--sim", "1:MG@can,2:MF@can236", "--bitrate", "500000"}
        << QString() << 2 << 500000;
    QTest::newRow("with a port") << QStringList{"--can", "sim", "--port", "/dev/ttyUSB0"}
                                 << QStringLiteral("cannot go with --port") << 0 << 0;
    QTest::newRow("bit rate with the RS485 simulator")
        << QStringList{"--sim", "1:MF", "--bitrate", "500000"} << QStringLiteral("--bitrate") << 0
        << 0;
}

void tst_StartupOptions::simulatedCan()
{
    // --can sim: the built-in simulated bus with its drives on CAN, whatever was remembered.
    QFETCH(QStringList, args);
    QFETCH(QString, refusal);
    QFETCH(int, simDrives);
    QFETCH(int, bitRate);
    std::optional<StartupOptions> o;
    QVERIFY(parsedAsExpected(args, refusal, &o));
    if (!o)
        return;
    QCOMPARE(o->sim ? int(o->sim->drives.size()) : 0, simDrives);
    AppSettings settings(m_dir.filePath(QString::fromLatin1(QTest::currentDataTag()) + ".ini"));
    ConnectionChoice remembered;
    remembered.kind = ConnectionChoice::Kind::Serial;
    remembered.port = QStringLiteral("/dev/ttyUSB0");
    settings.setConnection(remembered);
    const auto present = [](const QString &) { return true; };
    const ConnectionChoice c = o->initialChoice(settings, present);
    QVERIFY(c.isSimulator() && c.simulatedCan);
    QCOMPARE(c.link(), lk::protocol::Link::Can);
    QCOMPARE(c.bitRate, bitRate);
    QCOMPARE(c.rate(), bitRate);
    QVERIFY(!o->fellBackToSimulator(settings, present));
    // The simulator alone stays on RS485.
    const auto rs485 = StartupOptions::parse({"lkstudio", "--sim", "1:MF"}, nullptr);
    QVERIFY(!rs485->initialChoice(settings, present).simulatedCan);
}

QTEST_GUILESS_MAIN(tst_StartupOptions)
#include "tst_startupoptions.moc"
