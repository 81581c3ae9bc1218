#include <drive/DriveSettingsStore.h>
#include <main/AppSettings.h>
#include <main/MainWindow.h>
#include <main/SettingsFile.h>
#include <panels/MessageBanner.h>

#include <QtCore/QSettings>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QLabel>

using lk::ui::AppSettings;
using lk::ui::ConnectionChoice;

class tst_AppSettings : public QObject {
    Q_OBJECT
private slots:
    void init();
    void defaults();
    void roundTrip_data();
    void roundTrip();
    void migratesUnversioned_data();
    void migratesUnversioned();
    void leavesNewerFileAlone();
    void clampsScanRange();
    void language_data();
    void language();
    void damagedFileIsNamed_data();
    void damagedFileIsNamed();
    void cleanFileReportsNothing();
    void chosenSeriesPerPortAndId();
    void windowReportsDamageOnceAtStart();
    void sharesTheFileWithTheDriveStore();
    void canConnectionRoundTrip();
    void damagedCanValuesAreNotUsed();

private:
    QString file() const { return m_dir.filePath(QStringLiteral("lkstudio.ini")); }
    QTemporaryDir m_dir;
};

void tst_AppSettings::init()
{
    QFile::remove(file());
}

void tst_AppSettings::defaults()
{
    AppSettings s(file());
    QCOMPARE(s.loadedVersion(), 0);
    const ConnectionChoice c = s.connection();
    QVERIFY(c.isSimulator());
    QCOMPARE(c.baud, 115200);
    QVERIFY(c.autoReconnect);
    QCOMPARE(s.scanFirstId(), 1);
    QCOMPARE(s.scanLastId(), 32);
    QCOMPARE(s.pollRateHz(), 0.0);
}

void tst_AppSettings::roundTrip_data()
{
    QTest::addColumn<bool>("simulator");
    QTest::addColumn<QString>("port");
    QTest::addColumn<int>("baud");
    QTest::addColumn<bool>("autoReconnect");
    QTest::addColumn<bool>("listenOnly");
    QTest::newRow("serial") << false << QStringLiteral("/dev/ttyUSB0") << 1000000 << false << false;
    QTest::newRow("simulator") << true << QString() << 9600 << true << false;
    QTest::newRow("pty") << false << QStringLiteral("/dev/pts/7") << 2000000 << true << false;
    QTest::newRow("listening") << false << QStringLiteral("/dev/ttyUSB0") << 115200 << true << true;
}

void tst_AppSettings::roundTrip()
{
    QFETCH(bool, simulator);
    QFETCH(QString, port);
    QFETCH(int, baud);
    QFETCH(bool, autoReconnect);
    QFETCH(bool, listenOnly);
    ConnectionChoice c;
    c.kind = simulator ? ConnectionChoice::Kind::Simulator : ConnectionChoice::Kind::Serial;
    c.port = port;
    c.baud = baud;
    c.autoReconnect = autoReconnect;
    c.listenOnly = listenOnly;
    {
        AppSettings s(file());
        s.setConnection(c);
        s.setScanRange(3, 9, true);
        s.setPollRateHz(50);
        s.setCurrentView(QStringLiteral("traffic"));
        s.setWindow(QByteArray("geo"), QByteArray("state"));
    }
    AppSettings s(file());
    QCOMPARE(s.loadedVersion(), AppSettings::kVersion);
    QCOMPARE(s.connection(), c);
    QCOMPARE(s.scanFirstId(), 3);
    QCOMPARE(s.scanLastId(), 9);
    QVERIFY(s.scanSweepBauds());
    QCOMPARE(s.pollRateHz(), 50.0);
    QCOMPARE(s.currentView(), QStringLiteral("traffic"));
    QCOMPARE(s.windowGeometry(), QByteArray("geo"));
    QCOMPARE(s.windowState(), QByteArray("state"));
}

void tst_AppSettings::migratesUnversioned_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::addColumn<bool>("kept");
    QTest::newRow("good baud") << "connection/baud"
                               << "460800" << true;
    QTest::newRow("odd baud") << "connection/baud"
                              << "12345" << false;
    QTest::newRow("text baud") << "connection/baud"
                               << "fast" << false;
    QTest::newRow("good kind") << "connection/kind"
                               << "serial" << true;
    QTest::newRow("bad kind") << "connection/kind"
                              << "bluetooth" << false;
    QTest::newRow("good id") << "scan/firstId"
                             << "5" << true;
    QTest::newRow("id 0") << "scan/firstId"
                          << "0" << false;
    QTest::newRow("id 33") << "scan/lastId"
                           << "33" << false;
    QTest::newRow("bad bool") << "connection/autoReconnect"
                              << "maybe" << false;
    QTest::newRow("negative rate") << "poll/rateHz"
                                   << "-3" << false;
    QTest::newRow("port kept") << "connection/port"
                               << "ttyACM0" << true;
}

void tst_AppSettings::migratesUnversioned()
{
    QFETCH(QString, key);
    QFETCH(QString, value);
    QFETCH(bool, kept);
    {
        QSettings raw(file(), QSettings::IniFormat);
        raw.setValue(key, value);
    }
    {
        AppSettings s(file());
        QCOMPARE(s.loadedVersion(), 0);
    }
    QSettings raw(file(), QSettings::IniFormat);
    QCOMPARE(raw.value(QStringLiteral("settingsVersion")).toInt(), AppSettings::kVersion);
    QCOMPARE(raw.contains(key), kept);
    if (kept)
        QCOMPARE(raw.value(key).toString(), value);
}

void tst_AppSettings::leavesNewerFileAlone()
{
    const int future = AppSettings::kVersion + 1;
    {
        QSettings raw(file(), QSettings::IniFormat);
        raw.setValue(QStringLiteral("settingsVersion"), future);
        raw.setValue(QStringLiteral("connection/baud"), QStringLiteral("3000000"));
    }
    {
        AppSettings s(file());
        QVERIFY(s.isFromNewerRelease());
        QCOMPARE(s.connection().baud, 115200); // unknown here: read as the default
    }
    QSettings raw(file(), QSettings::IniFormat);
    QCOMPARE(raw.value(QStringLiteral("settingsVersion")).toInt(), future);
    QCOMPARE(raw.value(QStringLiteral("connection/baud")).toString(), QStringLiteral("3000000"));
}

void tst_AppSettings::clampsScanRange()
{
    AppSettings s(file());
    s.setScanRange(20, 40, false);
    QCOMPARE(s.scanFirstId(), 20);
    QCOMPARE(s.scanLastId(), 32);
    s.setScanRange(12, 4, false);
    QCOMPARE(s.scanLastId(), 12); // last never before first
}

void tst_AppSettings::language_data()
{
    QTest::addColumn<QString>("written");
    QTest::addColumn<QString>("read");
    QTest::newRow("system default") << QString() << QString();
    QTest::newRow("chinese") << QStringLiteral("zh_CN") << QStringLiteral("zh_CN");
    QTest::newRow("english") << QStringLiteral("en") << QStringLiteral("en");
    QTest::newRow("garbage") << QStringLiteral("../x") << QString();
}

void tst_AppSettings::language()
{
    QFETCH(QString, written);
    QFETCH(QString, read);
    {
        AppSettings s(file());
        QCOMPARE(s.language(), QString()); // default: follow the system
        s.setLanguage(written);
    }
    AppSettings s(file());
    QCOMPARE(s.language(), read);
    // A bad value typed into the file by hand reads as the system default.
    QSettings raw(file(), QSettings::IniFormat);
    raw.setValue(QStringLiteral("ui/language"), QStringLiteral("zh CN!"));
    raw.sync();
    QCOMPARE(AppSettings(file()).language(), QString());
}

void tst_AppSettings::damagedFileIsNamed_data()
{
    QTest::addColumn<int>("version");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("named");
    QTest::newRow("baud") << 1 << "connection/baud"
                          << "12345"
                          << "connection/baud: must be";
    QTest::newRow("baud unversioned") << 0 << "connection/baud"
                                      << "12345"
                                      << "connection/baud: must be";
    QTest::newRow("scan id") << 1 << "scan/firstId"
                             << "99"
                             << "scan/firstId: must be 1..32";
    QTest::newRow("poll rate") << 1 << "poll/rateHz"
                               << "fast"
                               << "poll/rateHz: must be";
    QTest::newRow("drive limits") << 1 << "drives/id1-MF4015/softLimits"
                                  << R"({"max_speed": 720})"
                                  << "drives/id1-MF4015/softLimits: unknown key \"max_speed\"";
    QTest::newRow("drive limits duplicate") << 1 << "drives/id1-MF4015/softLimits"
                                            << R"({"max_speed_dps": 1, "max_speed_dps": 2})"
                                            << "\"max_speed_dps\" is given twice";
    QTest::newRow("listen only") << 1 << "connection/listenOnly"
                                 << "maybe"
                                 << "connection/listenOnly: must be true or false";
    QTest::newRow("chosen series") << 1 << "chosenSeries/%2Fdev%2FttyUSB0/5"
                                   << "MX"
                                   << "chosenSeries/%2Fdev%2FttyUSB0/5: must be MS, MF, MG or MH";
    QTest::newRow("gear ratio") << 1 << "drives/id2-MG5010E-i10/gearRatio"
                                << "0.5"
                                << "drives/id2-MG5010E-i10/gearRatio: must be";
    QTest::newRow("can bit rate") << 1 << "connection/canBitRate"
                                  << "800000"
                                  << "connection/canBitRate: must be 1000000, 500000, 250000";
    QTest::newRow("can plugin") << 1 << "connection/canPlugin"
                                << "socket can"
                                << "connection/canPlugin: must be a Qt CAN plugin";
    QTest::newRow("chosen generation") << 1 << "chosenGeneration/simulator-can/4"
                                       << "v2.4"
                                       << "chosenGeneration/simulator-can/4: must be can or can236";
    QTest::newRow("connection kind") << 1 << "connection/kind"
                                     << "modem"
                                     << "serial, can, simulator or simulator-can";
    QTest::newRow("can interface") << 1 << "connection/canInterface"
                                   << "can 0"
                                   << "connection/canInterface: must be an interface name";
}

void tst_AppSettings::canConnectionRoundTrip()
{
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Can;
    c.port = QStringLiteral("/dev/ttyUSB0");
    c.canPlugin = QStringLiteral("virtualcan");
    c.canInterface = QStringLiteral("tcp://127.0.0.1:35468/can1");
    c.bitRate = 125000;
    c.listenOnly = true;
    {
        AppSettings s(file());
        s.setConnection(c);
    }
    AppSettings s(file());
    QVERIFY(s.damage().isEmpty());
    QCOMPARE(s.connection(), c);
    // The built-in simulator on CAN is remembered as such, apart from the RS485 one.
    c.kind = ConnectionChoice::Kind::Simulator;
    c.simulatedCan = true;
    c.listenOnly = false;
    s.setConnection(c);
    QCOMPARE(AppSettings(file()).connection(), c);
    c.simulatedCan = false;
    s.setConnection(c);
    QCOMPARE(AppSettings(file()).connection(), c);
}

void tst_AppSettings::damagedCanValuesAreNotUsed()
{
    {
        QSettings raw(file(), QSettings::IniFormat);
        raw.setValue(QStringLiteral("settingsVersion"), 1);
        raw.setValue(QStringLiteral("connection/kind"), QStringLiteral("can"));
        raw.setValue(QStringLiteral("connection/canBitRate"), QStringLiteral("fast"));
        raw.setValue(QStringLiteral("connection/canInterface"), QString());
    }
    AppSettings s(file());
    QCOMPARE(s.damage().size(), 2); // both named (an empty interface is no interface)
    const ConnectionChoice c = s.connection();
    QVERIFY(c.isCan());
    QCOMPARE(c.bitRate, 1000000); // the drives' default, never a guess from the damage
    QCOMPARE(c.canInterface, QStringLiteral("can0"));
}

void tst_AppSettings::damagedFileIsNamed()
{
    QFETCH(int, version);
    QFETCH(QString, key);
    QFETCH(QString, value);
    QFETCH(QString, named);
    {
        QSettings raw(file(), QSettings::IniFormat);
        if (version > 0)
            raw.setValue(QStringLiteral("settingsVersion"), version);
        raw.setValue(key, value);
    }
    AppSettings s(file());
    QCOMPARE(s.damage().size(), 1);
    QVERIFY2(s.damage().first().contains(named), qPrintable(s.damage().first()));
    QVERIFY(s.damageReport().contains(file()));
    QVERIFY(s.damageReport().contains(key));
}

void tst_AppSettings::chosenSeriesPerPortAndId()
{
    using lk::protocol::Series;
    {
        AppSettings s(file());
        s.setChosenSeries(QStringLiteral("/dev/ttyUSB0"), 5, Series::MS);
        s.setChosenSeries(QStringLiteral("/dev/ttyUSB1"), 5, Series::MG);
        s.setChosenSeries(QStringLiteral("simulator"), 7, Series::MH);
    }
    AppSettings s(file());
    QVERIFY(s.damage().isEmpty());
    QCOMPARE(s.chosenSeries(QStringLiteral("/dev/ttyUSB0"), 5), std::optional(Series::MS));
    QCOMPARE(s.chosenSeries(QStringLiteral("/dev/ttyUSB1"), 5), std::optional(Series::MG));
    QCOMPARE(s.chosenSeries(QStringLiteral("simulator"), 7), std::optional(Series::MH));
    QVERIFY(!s.chosenSeries(QStringLiteral("/dev/ttyUSB0"), 6)); // never chosen: unknown
    QVERIFY(!s.chosenSeries(QStringLiteral("/dev/ttyUSB2"), 5));
    // The CAN generation beside it, per port and ID.
    using lk::protocol::Generation;
    s.setChosenGeneration(QStringLiteral("can:socketcan:can0"), 5, Generation::V2_35);
    s.setChosenGeneration(QStringLiteral("can:socketcan:can0"), 6, Generation::V2_3);
    const AppSettings again(file());
    QVERIFY(again.damage().isEmpty());
    QCOMPARE(again.chosenGeneration(QStringLiteral("can:socketcan:can0"), 5),
             std::optional(Generation::V2_35));
    QCOMPARE(again.chosenGeneration(QStringLiteral("can:socketcan:can0"), 6),
             std::optional(Generation::V2_3));
    QVERIFY(!again.chosenGeneration(QStringLiteral("can:socketcan:can1"), 5));
}

void tst_AppSettings::cleanFileReportsNothing()
{
    {
        AppSettings s(file());
        s.setScanRange(3, 9, true);
        s.setPollRateHz(50);
    }
    {
        QSettings raw(file(), QSettings::IniFormat);
        raw.setValue(QStringLiteral("drives/id1-MF4015/softLimits"),
                     QStringLiteral(R"({"max_speed_dps":720,"max_torque_a":1})"));
        raw.setValue(QStringLiteral("drives/id1-MF4015/encoderBits"), 14);
    }
    AppSettings s(file());
    QCOMPARE(s.damage(), QStringList());
    QCOMPARE(s.damageReport(), QString());
}

void tst_AppSettings::windowReportsDamageOnceAtStart()
{
    {
        QSettings raw(file(), QSettings::IniFormat);
        raw.setValue(QStringLiteral("settingsVersion"), 1);
        raw.setValue(QStringLiteral("drives/id1-MF4015/softLimits"),
                     QStringLiteral(R"({"max_speed": 720})"));
    }
    AppSettings settings(file());
    lk::ui::MainWindow window(&settings);
    window.show();
    QTRY_VERIFY_WITH_TIMEOUT(window.banner()->text().contains(QStringLiteral("max_speed")), 20000);
    QCOMPARE(window.banner()->level(), lk::ui::MessageBanner::Level::Warning);
    QTest::qWait(100);
    // Told once: the transient line shows the message itself, with no "(\u00d72)" count.
    const auto *line = window.banner()->findChild<QLabel *>(QStringLiteral("messageText"));
    QVERIFY(line);
    QCOMPARE(line->text(), window.banner()->text());
}

void tst_AppSettings::sharesTheFileWithTheDriveStore()
{
    const QString drive = QStringLiteral("id1-MF4015");
    {
        // As lkstudio runs: one file, the window's settings and the drive views' store in it,
        // their writes interleaved.
        lk::ui::SettingsFile shared(file());
        AppSettings s(shared);
        lk::ui::IniDriveStore drives(shared.settings());
        s.setPollRateHz(50);
        drives.setEncoderBits(drive, 16);
        s.sync();
        s.setScanRange(3, 9, true);
        drives.setGearRatio(drive, 6);
        drives.sync();
        s.setLanguage(QStringLiteral("zh_CN"));
    }
    lk::ui::SettingsFile reopened(file());
    AppSettings s(reopened);
    lk::ui::IniDriveStore drives(reopened.settings());
    QCOMPARE(s.damage(), QStringList());
    QCOMPARE(s.pollRateHz(), 50.0);
    QCOMPARE(s.scanFirstId(), 3);
    QCOMPARE(s.scanLastId(), 9);
    QCOMPARE(s.language(), QStringLiteral("zh_CN"));
    QCOMPARE(drives.encoderBits(drive), std::optional<int>(16));
    QCOMPARE(drives.gearRatio(drive), std::optional<double>(6));
}

QTEST_MAIN(tst_AppSettings)
#include "tst_appsettings.moc"
