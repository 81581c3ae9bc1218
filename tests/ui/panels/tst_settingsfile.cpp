// The files lkstudio reads at start are looked at before they are read: a settings INI that
// is a directory, a FIFO or far too large is neither read nor written, and the user is told
// (the settings banner, naming the file); --settings such a file is refused; a file from a
// newer release is named by its settingsVersion key. os-release is bounded the same way.

#include <main/AppSettings.h>
#include <main/MainWindow.h>
#include <main/SettingsFile.h>
#include <main/StartupOptions.h>
#include <panels/MessageBanner.h>
#include <panels/SerialGroupAdvice.h>

#include "../../support/OddFiles.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFileInfo>
#include <QtCore/QSettings>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::testsupport::OddFiles;
using lk::ui::AppSettings;
using lk::ui::SettingsFile;

class tst_SettingsFile : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void refusedFile_data();
    void refusedFile();
    void refusedOnTheCommandLine_data() { refusedFile_data(); }
    void refusedOnTheCommandLine();
    void newerReleaseIsNamed();
    void windowTellsAboutARefusedFile();
    void defaultPathIsQSettingsOwn();
    void osReleaseIsBounded();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }
    QTemporaryDir m_dir;
};

void tst_SettingsFile::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true); // never the user's own settings
}

void tst_SettingsFile::refusedFile_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("said");
    QTest::newRow("directory") << int(OddFiles::Kind::Directory) << "it is a directory";
    QTest::newRow("FIFO") << int(OddFiles::Kind::Fifo) << "it is a FIFO";
    QTest::newRow("2 MB") << int(OddFiles::Kind::Huge) << "it is 2.0 MB, more than the 1.0 MB";
}

void tst_SettingsFile::refusedFile()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    const QString ini = path(QStringLiteral("refused-%1.ini").arg(kind));
    QVERIFY(!OddFiles::make(OddFiles::Kind(kind), ini, 2'000'000).isEmpty());
    const QFileInfo before(ini);
    QElapsedTimer clock;
    clock.start();
    {
        AppSettings s(ini);
        QVERIFY(clock.elapsed() < 5000); // a FIFO without a writer must not hang the start
        QVERIFY(s.file().problem());
        QCOMPARE(s.fileName(), ini);
        QCOMPARE(s.damage().size(), 1);
        QVERIFY2(s.damage().first().startsWith(ini), qPrintable(s.damage().first()));
        const QString report = s.damageReport();
        QVERIFY2(report.contains(ini) && report.contains(said), qPrintable(report));
        QVERIFY2(report.contains(QLatin1String("not saved")), qPrintable(report));
        // Defaults meanwhile, and what changes lives in memory.
        QCOMPARE(s.pollRateHz(), AppSettings(path(QStringLiteral("fresh.ini"))).pollRateHz());
        s.setScanRange(3, 9, false);
        QCOMPARE(s.scanFirstId(), 3);
    }
    // Neither read nor written: the same kind of node, the same size.
    const QFileInfo after(ini);
    QCOMPARE(after.isDir(), before.isDir());
    QCOMPARE(after.isFile(), before.isFile());
    if (before.isFile())
        QCOMPARE(after.size(), before.size());
}

void tst_SettingsFile::refusedOnTheCommandLine()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    const QString ini = path(QStringLiteral("option-%1.ini").arg(kind));
    QVERIFY(!OddFiles::make(OddFiles::Kind(kind), ini, 2'000'000).isEmpty());
    QString error;
    QVERIFY(!lk::ui::StartupOptions::parse({"lkstudio", "--settings", ini}, &error));
    QVERIFY2(error.startsWith(QStringLiteral("--settings ") + ini), qPrintable(error));
    QVERIFY2(error.contains(said), qPrintable(error));
    // A settings file that does not exist yet is fine: it is created.
    QVERIFY(lk::ui::StartupOptions::parse(
        {"lkstudio", "--settings", path(QStringLiteral("new.ini"))}, &error));
}

void tst_SettingsFile::newerReleaseIsNamed()
{
    const QString ini = path(QStringLiteral("newer.ini"));
    {
        QSettings raw(ini, QSettings::IniFormat);
        raw.setValue(QStringLiteral("settingsVersion"), 999);
        raw.setValue(QStringLiteral("scan/firstId"), 4);
    }
    AppSettings s(ini);
    QVERIFY(s.isFromNewerRelease());
    QCOMPARE(s.damage(), QStringList());
    const QString report = s.damageReport();
    QVERIFY2(report.contains(QLatin1String("settingsVersion is 999")), qPrintable(report));
    QVERIFY2(report.contains(ini), qPrintable(report));
    QCOMPARE(s.scanFirstId(), 4); // what this release understands is used
}

void tst_SettingsFile::windowTellsAboutARefusedFile()
{
    const QString ini = path(QStringLiteral("window.ini"));
    QVERIFY(QDir().mkpath(ini));
    AppSettings settings(ini);
    lk::ui::MainWindow window(&settings);
    window.show();
    QTRY_VERIFY_WITH_TIMEOUT(window.banner()->text().contains(QLatin1String("it is a directory")),
                             20000);
    QCOMPARE(window.banner()->level(), lk::ui::MessageBanner::Level::Warning);
    QVERIFY(window.banner()->text().contains(ini));
}

void tst_SettingsFile::defaultPathIsQSettingsOwn()
{
    const QSettings own(QSettings::IniFormat, QSettings::UserScope, QStringLiteral("lkstudio"),
                        QStringLiteral("lkstudio"));
    QCOMPARE(SettingsFile::defaultPath(), own.fileName());
}

void tst_SettingsFile::osReleaseIsBounded()
{
    const QString good = path(QStringLiteral("os-release"));
    QFile f(good);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("ID=arch\nNAME=\"Arch Linux\"\n");
    f.close();
    const QString fifo = OddFiles::make(OddFiles::Kind::Fifo, path(QStringLiteral("os-fifo")));
    const QString huge =
        OddFiles::make(OddFiles::Kind::Huge, path(QStringLiteral("os-huge")), 1'000'000'000);
    QVERIFY(!fifo.isEmpty() && !huge.isEmpty());
    QElapsedTimer clock;
    clock.start();
    const auto advice = lk::ui::SerialGroupAdvice::fromFirstReadable({fifo, huge, good});
    QVERIFY(clock.elapsed() < 5000);
    QCOMPARE(advice.group, QStringLiteral("uucp")); // the odd ones skipped, the good one read
    QCOMPARE(lk::ui::SerialGroupAdvice::fromFirstReadable({fifo, huge}).known, false);
}

QTEST_MAIN(tst_SettingsFile)
#include "tst_settingsfile.moc"
