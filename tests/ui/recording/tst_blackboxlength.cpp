// The black box's length is a setting (recording/blackBoxMinutes, 1..60 minutes, 10 unless
// set): read at start, changed from the File menu for the ring running now and the next
// connection, kept; a bad value in the file is damage named by its key, one asked for is
// refused with the key named, and the ring keeps what it kept.
#include "../MainWindowFixture.h"

#include <recording/BlackBox.h>

#include <QtCore/QFile>
#include <QtGui/QAction>

using namespace lk;

namespace {
constexpr qint64 kMinuteNs = 60LL * 1'000'000'000;
} // namespace

class tst_BlackBoxLength : public uitest::MainWindowFixture {
    Q_OBJECT
private slots:
    void cleanup() { closeWindow(); }
    void fileValues_data();
    void fileValues();
    void readAtStartAndUsedByTheRing();
    void changedForTheRunningRingAndKept();
    void outOfRangeIsRefusedWithTheKeyNamed_data();
    void outOfRangeIsRefusedWithTheKeyNamed();

private:
    /// A window on a settings file that holds `ini`.
    bool openWindowOn(const QByteArray &ini)
    {
        m_dir = std::make_unique<QTemporaryDir>();
        QFile f(m_dir->filePath("lkstudio.ini"));
        if (!f.open(QIODevice::WriteOnly) || f.write(ini) != ini.size())
            return false;
        f.close();
        m_settings = std::make_unique<ui::AppSettings>(f.fileName());
        m_window = std::make_unique<ui::MainWindow>(m_settings.get());
        m_window->recording()->blackBox()->setFolder(m_dir->filePath("recordings"));
        m_window->show();
        return QTest::qWaitForWindowExposed(m_window.get());
    }
    ui::BlackBoxRecorder *recorder() const { return m_window->recording()->blackBox(); }
};

void tst_BlackBoxLength::fileValues_data()
{
    QTest::addColumn<QByteArray>("value");
    QTest::addColumn<int>("minutes");
    QTest::addColumn<bool>("damaged");
    QTest::newRow("set") << QByteArray("25") << 25 << false;
    QTest::newRow("shortest") << QByteArray("1") << 1 << false;
    QTest::newRow("longest") << QByteArray("60") << 60 << false;
    QTest::newRow("zero") << QByteArray("0") << 10 << true;
    QTest::newRow("past the bound") << QByteArray("61") << 10 << true;
    QTest::newRow("negative") << QByteArray("-5") << 10 << true;
    QTest::newRow("not a number") << QByteArray("ten") << 10 << true;
}

void tst_BlackBoxLength::fileValues()
{
    QFETCH(QByteArray, value);
    QFETCH(int, minutes);
    QFETCH(bool, damaged);
    QTemporaryDir dir;
    QFile f(dir.filePath("s.ini"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("[General]\nsettingsVersion=1\n[recording]\nblackBoxMinutes=" + value + "\n");
    f.close();
    ui::AppSettings settings(f.fileName());
    QCOMPARE(settings.blackBoxMinutes(), minutes);
    const QString damage = settings.damage().join(QLatin1Char('\n'));
    QCOMPARE(damage.contains(QLatin1String("recording/blackBoxMinutes")), damaged);
    if (damaged) // never silently: the banner's report names the key too
        QVERIFY2(settings.damageReport().contains(QLatin1String("recording/blackBoxMinutes")),
                 qPrintable(settings.damageReport()));
}

void tst_BlackBoxLength::readAtStartAndUsedByTheRing()
{
    QVERIFY(openWindowOn("[General]\nsettingsVersion=1\n[recording]\nblackBoxMinutes=25\n"));
    QCOMPARE(recorder()->windowMinutes(), 25);
    QVERIFY2(m_window->recording()->saveAction()->text().contains(QLatin1String("25")),
             qPrintable(m_window->recording()->saveAction()->text()));
    QVERIFY(connectToSimulator());
    QVERIFY(recorder()->box());
    QCOMPARE(recorder()->box()->windowNs(), 25 * kMinuteNs);
}

void tst_BlackBoxLength::changedForTheRunningRingAndKept()
{
    QVERIFY(openWindow());
    QCOMPARE(recorder()->windowMinutes(), 10); // the default
    QVERIFY(connectToSimulator());
    QCOMPARE(recorder()->box()->windowNs(), 10 * kMinuteNs);
    QVERIFY(m_window->recording()->lengthAction());
    QVERIFY(m_window->recording()->setBlackBoxMinutes(3));
    QCOMPARE(recorder()->box()->windowNs(), 3 * kMinuteNs); // the running ring, now
    QCOMPARE(m_settings->blackBoxMinutes(), 3);
    QVERIFY(m_window->recording()->saveAction()->text().contains(QLatin1String("3")));
    m_settings->sync();
    QCOMPARE(ui::AppSettings(m_settings->fileName()).blackBoxMinutes(), 3);
}

void tst_BlackBoxLength::outOfRangeIsRefusedWithTheKeyNamed_data()
{
    QTest::addColumn<int>("minutes");
    QTest::newRow("0") << 0;
    QTest::newRow("61") << 61;
    QTest::newRow("-1") << -1;
}

void tst_BlackBoxLength::outOfRangeIsRefusedWithTheKeyNamed()
{
    QFETCH(int, minutes);
    QVERIFY(openWindow());
    QVERIFY(connectToSimulator());
    QVERIFY(!m_window->recording()->setBlackBoxMinutes(minutes));
    const QString entry = m_window->banner()->entryText(ui::RecordingController::entryKey());
    QVERIFY2(entry.contains(QLatin1String("recording/blackBoxMinutes")), qPrintable(entry));
    QCOMPARE(recorder()->windowMinutes(), 10);
    QCOMPARE(recorder()->box()->windowNs(), 10 * kMinuteNs);
    QCOMPARE(m_settings->blackBoxMinutes(), 10);
    QVERIFY(!m_settings->setBlackBoxMinutes(minutes));
}

QTEST_MAIN(tst_BlackBoxLength)
#include "tst_blackboxlength.moc"
