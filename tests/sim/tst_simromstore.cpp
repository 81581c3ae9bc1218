#include "sim/SimRomStore.h"

#include "../support/FileSizeLimit.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QLoggingCategory>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

using lk::protocol::PidGains;
using lk::protocol::Series;
using lk::sim::SimRom;
using lk::sim::SimRomStore;

namespace {
void writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}

const char *const kValid = R"({"format":"lk-sim-rom","version":1,"id":5,"series":"MF",
"pid":{"angle_kp":1,"angle_ki":2,"speed_kp":3,"speed_ki":4,"iq_kp":5,"iq_ki":6},
"accel_dps2":-7,"encoder_zero":65535})";
} // namespace

/// ROM persistence: round trip, and every kind of bad file handled without a crash.
class tst_SimRomStore : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void roundTrip();
    void handWrittenFile();
    void corruptFile_data();
    void corruptFile();
    void unreadableFile();
    void danglingLink();
    void otherSeries();
    void memoryOnly();
    void unwritableDirectory();
    void diskFullKeepsTheEarlierRom();
};

void tst_SimRomStore::initTestCase()
{
    // Every test checks errors() itself; the same sentences on the log are only noise here.
    QLoggingCategory::setFilterRules(QStringLiteral("lk.sim.warning=false"));
}

void tst_SimRomStore::roundTrip()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const SimRom rom{PidGains{255, 0, 7, 8, 9, 10}, 123456, 4321, {}};
    {
        SimRomStore store(dir.path());
        QVERIFY(!store.rom(3, Series::MF));
        QVERIFY(store.save(3, Series::MF, rom));
        QCOMPARE(store.rom(3, Series::MF), std::optional<SimRom>(rom));
        QVERIFY(QFile::exists(store.filePath(3)));
        QVERIFY(store.filePath(3).endsWith(QLatin1String("rom-id03.json")));
    }
    SimRomStore again(dir.path());
    QCOMPARE(again.rom(3, Series::MF), std::optional<SimRom>(rom));
    QVERIFY(!again.rom(4, Series::MF));
    QVERIFY(again.errors().isEmpty());
}

void tst_SimRomStore::handWrittenFile()
{
    QTemporaryDir dir;
    writeFile(dir.filePath(QStringLiteral("rom-id05.json")), kValid);
    SimRomStore store(dir.path());
    QVERIFY2(store.errors().isEmpty(), qPrintable(store.errors().join('\n')));
    const auto rom = store.rom(5, Series::MF);
    QVERIFY(rom);
    QCOMPARE(rom->pid, (PidGains{1, 2, 3, 4, 5, 6}));
    QCOMPARE(rom->accelDps2, -7);
    QCOMPARE(rom->encoderZero, quint16(65535));
}

void tst_SimRomStore::corruptFile_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("mentions");
    const QByteArray valid(kValid);
    QTest::newRow("empty") << QByteArray() << "invalid JSON";
    QTest::newRow("binary") << QByteArray("\x00\xff\x3e\x9c", 4) << "invalid JSON";
    QTest::newRow("truncated") << valid.left(valid.size() / 2) << "invalid JSON";
    QTest::newRow("array") << QByteArray("[1,2]") << "not a JSON object";
    QTest::newRow("other format") << QByteArray(valid).replace("lk-sim-rom", "other") << "format";
    QTest::newRow("future version")
        << QByteArray(valid).replace("\"version\":1", "\"version\":2") << "version";
    QTest::newRow("id mismatch") << QByteArray(valid).replace("\"id\":5", "\"id\":6") << "\"id\"";
    QTest::newRow("bad series") << QByteArray(valid).replace("\"MF\"", "\"MX\"") << "series";
    QTest::newRow("gain over 255")
        << QByteArray(valid).replace("\"iq_ki\":6", "\"iq_ki\":256") << "pid.iq_ki";
    QTest::newRow("gain fractional")
        << QByteArray(valid).replace("\"angle_kp\":1", "\"angle_kp\":1.5") << "pid.angle_kp";
    QTest::newRow("gain missing") << QByteArray(valid).replace("\"speed_ki\":4,", "")
                                  << "pid.speed_ki";
    QTest::newRow("accel text") << QByteArray(valid).replace("-7", "\"fast\"") << "accel_dps2";
    QTest::newRow("zero too big") << QByteArray(valid).replace("65535", "65536") << "encoder_zero";
}

void tst_SimRomStore::corruptFile()
{
    QFETCH(QByteArray, content);
    QFETCH(QString, mentions);
    QTemporaryDir dir;
    writeFile(dir.filePath(QStringLiteral("rom-id05.json")), content);
    SimRomStore store(dir.path());
    QVERIFY(!store.rom(5, Series::MF)); // defaults are used
    QCOMPARE(store.errors().size(), 1);
    QVERIFY2(store.errors().first().contains(mentions), qPrintable(store.errors().first()));
    QVERIFY(store.errors().first().contains(QLatin1String("rom-id05.json")));
    // Saving afterwards replaces the bad file.
    QVERIFY(store.save(5, Series::MF, SimRom{}));
    SimRomStore again(dir.path());
    QCOMPARE(again.rom(5, Series::MF), std::optional<SimRom>(SimRom{}));
}

void tst_SimRomStore::unreadableFile()
{
    // A directory where the file should be: cannot be opened for reading (even as root).
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("rom-id07.json")));
    SimRomStore store(dir.path());
    QVERIFY(!store.rom(7, Series::MF));
    QCOMPARE(store.errors().size(), 1);
    QVERIFY(store.errors().first().contains(QLatin1String("Cannot read")));
    QVERIFY(store.errors().first().contains(QLatin1String("rom-id07.json")));
    // ... and cannot be written either: save reports it and keeps the value in memory.
    const SimRom rom{PidGains{1, 1, 1, 1, 1, 1}, 1, 1, {}};
    QVERIFY(!store.save(7, Series::MF, rom));
    QVERIFY(store.errors().last().contains(QLatin1String("Cannot write")));
    QCOMPARE(store.rom(7, Series::MF), std::optional<SimRom>(rom));
}

void tst_SimRomStore::danglingLink()
{
    QTemporaryDir dir;
    QVERIFY(QFile::link(dir.filePath(QStringLiteral("missing")),
                        dir.filePath(QStringLiteral("rom-id08.json"))));
    SimRomStore store(dir.path());
    QVERIFY(!store.rom(8, Series::MF));
    QCOMPARE(store.errors().size(), 1);
    QVERIFY(store.errors().first().contains(QLatin1String("Cannot read")));
}

void tst_SimRomStore::otherSeries()
{
    QTemporaryDir dir;
    writeFile(dir.filePath(QStringLiteral("rom-id05.json")), kValid); // an MF drive's ROM
    SimRomStore store(dir.path());
    QVERIFY(!store.rom(5, Series::MS));
    QCOMPARE(store.errors().size(), 1);
    QVERIFY(store.errors().first().contains(QLatin1String("MF")));
    QVERIFY(store.rom(5, Series::MF));
}

void tst_SimRomStore::memoryOnly()
{
    SimRomStore store;
    QVERIFY(!store.persistent());
    QVERIFY(store.save(1, Series::MG, SimRom{}));
    QCOMPARE(store.rom(1, Series::MG), std::optional<SimRom>(SimRom{}));
    QVERIFY(store.errors().isEmpty());
}

void tst_SimRomStore::unwritableDirectory()
{
    // The directory path is a regular file: it can be neither created nor written.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("not-a-dir"));
    writeFile(path, "x");
    SimRomStore store(path);
    QCOMPARE(store.errors().size(), 1);
    QVERIFY(store.errors().first().contains(QLatin1String("Cannot create")));
    QVERIFY(!store.save(1, Series::MF, SimRom{}));
    QCOMPARE(store.errors().size(), 2);
}

void tst_SimRomStore::diskFullKeepsTheEarlierRom()
{
    // The ROM file is small: it stays in QSaveFile's buffer until the last flush, where a
    // full disk must still leave the earlier file whole.
    QTemporaryDir dir;
    const SimRom before{PidGains{1, 2, 3, 4, 5, 6}, 100, 200, {}};
    SimRomStore store(dir.path());
    QVERIFY(store.save(2, Series::MF, before));
    QFile file(store.filePath(2));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray earlier = file.readAll();
    file.close();
    {
        const lk::testsupport::FileSizeLimit diskFull(16);
        QVERIFY(diskFull.isActive());
        QVERIFY(!store.save(2, Series::MF, SimRom{PidGains{9, 9, 9, 9, 9, 9}, 1, 2, {}}));
    }
    QVERIFY(store.errors().last().contains(QLatin1String("Cannot write ROM file")));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), earlier);
    QCOMPARE(SimRomStore(dir.path()).rom(2, Series::MF), std::optional<SimRom>(before));
}

QTEST_APPLESS_MAIN(tst_SimRomStore)
#include "tst_simromstore.moc"
