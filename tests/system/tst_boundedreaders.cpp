// Every reader of a file a user hands the tools goes through BoundedFile: a FIFO without a
// writer, a directory, /dev/zero and a file far past the reader's bound are refused at once,
// with the file and what it is (or its size) named, and nothing half-read is used.

#include <record/ParameterSet.h>
#include <sim/SimRomStore.h>
#include <tuning/StepRunFile.h>

#include "../support/OddFiles.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QLoggingCategory>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::testsupport::OddFiles;
using namespace lk;

namespace {

constexpr qint64 kHuge = 3'000'000'000; // sparse: no disk, no time

tuning::StepRun smallRun()
{
    tuning::StepRun run;
    run.number = 1;
    run.driveId = 3;
    run.series = "MF";
    run.model = "MF4015";
    run.generation = "v2.3";
    run.spec = {tuning::StepLoop::Speed, 0, 360, 0.5, 1};
    for (int i = 0; i < 10; ++i)
        run.trace.append(i * 0.01, i * 36.0, 0.1);
    run.trace.edges = {tuning::StepEdge{0.0, 0, 360}};
    return run;
}

/// The odd file of `kind` at `path` (or /dev/zero); fails the test when it cannot be made.
QString odd(int kind, const QString &path)
{
    const QString made = OddFiles::make(OddFiles::Kind(kind), path, kHuge);
    if (made.isEmpty())
        qFatal("cannot make %s", qPrintable(path));
    return made;
}

/// A step-run set on disk whose trace `csv` (run1's) is then replaced by `kind`.
QString runSetWithOddTrace(const QTemporaryDir &dir, int kind)
{
    const QString json = dir.filePath(QStringLiteral("set.lkruns.json"));
    if (!tuning::StepRunFile::save(json, {smallRun()}).isEmpty())
        qFatal("cannot save a run set");
    const QString csv = dir.filePath(QStringLiteral("set.run1.csv"));
    QFile::remove(csv);
    if (OddFiles::Kind(kind) == OddFiles::Kind::Device)
        QFile::link(QStringLiteral("/dev/zero"), csv);
    else
        odd(kind, csv);
    return json;
}

} // namespace

class tst_BoundedReaders : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void oddFile_data();
    void parameterSet_data() { oddFile_data(); }
    void parameterSet();
    void stepRunJson_data() { oddFile_data(); }
    void stepRunJson();
    void stepRunTrace_data() { oddFile_data(); }
    void stepRunTrace();
    void simRom_data() { oddFile_data(); }
    void simRom();
    void stepRunSetBudget();
    void stepRunSaveRefusesWhatLoadWould();
};

void tst_BoundedReaders::initTestCase()
{
    QLoggingCategory::setFilterRules(QStringLiteral("lk.sim.warning=false"));
}

void tst_BoundedReaders::oddFile_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("said"); // what the error names
    QTest::newRow("FIFO") << int(OddFiles::Kind::Fifo) << "FIFO";
    QTest::newRow("directory") << int(OddFiles::Kind::Directory) << "directory";
    QTest::newRow("/dev/zero") << int(OddFiles::Kind::Device) << "character device";
    QTest::newRow("3 GB") << int(OddFiles::Kind::Huge) << "3000.0 MB";
}

void tst_BoundedReaders::parameterSet()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    QTemporaryDir dir;
    const QString path = odd(kind, dir.filePath(QStringLiteral("gains.json")));
    QElapsedTimer clock;
    clock.start();
    record::ParameterFileError error;
    QVERIFY(!record::ParameterSet::load(path, &error));
    QVERIFY(clock.elapsed() < 5000);
    QCOMPARE(error.path, path);
    QVERIFY2(error.detail.contains(said), qPrintable(error.detail));
    if (OddFiles::Kind(kind) == OddFiles::Kind::Huge) {
        QCOMPARE(error.kind, record::ParameterFileError::Kind::TooLarge);
        QCOMPARE(error.max, double(record::ParameterSet::kMaxFileBytes));
        QCOMPARE(error.found, QString::number(kHuge));
    } else {
        QCOMPARE(error.kind, record::ParameterFileError::Kind::CannotRead);
    }
}

void tst_BoundedReaders::stepRunJson()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    QTemporaryDir dir;
    const QString path = odd(kind, dir.filePath(QStringLiteral("set.lkruns.json")));
    tuning::StepRunFileError error;
    QVERIFY(!tuning::StepRunFile::load(path, &error));
    QCOMPARE(error.path, path);
    QVERIFY2(error.toString().contains(said), qPrintable(error.toString()));
    QCOMPARE(error.kind, OddFiles::Kind(kind) == OddFiles::Kind::Huge
                             ? tuning::StepRunFileError::Kind::TooLarge
                             : tuning::StepRunFileError::Kind::CannotRead);
}

void tst_BoundedReaders::stepRunTrace()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    QTemporaryDir dir;
    const QString json = runSetWithOddTrace(dir, kind);
    QElapsedTimer clock;
    clock.start();
    tuning::StepRunFileError error;
    QVERIFY(!tuning::StepRunFile::load(json, &error));
    QVERIFY(clock.elapsed() < 5000);
    QCOMPARE(error.path, dir.filePath(QStringLiteral("set.run1.csv")));
    QVERIFY2(error.toString().contains(said), qPrintable(error.toString()));
    if (OddFiles::Kind(kind) == OddFiles::Kind::Huge) {
        QCOMPARE(error.kind, tuning::StepRunFileError::Kind::TooLarge);
        QCOMPARE(error.max, double(tuning::StepRunFile::kMaxTraceBytes));
    } else {
        QCOMPARE(error.kind, tuning::StepRunFileError::Kind::MissingTrace);
        QCOMPARE(error.key, QStringLiteral("runs[0].trace"));
    }
}

void tst_BoundedReaders::simRom()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rom-id05.json"));
    if (OddFiles::Kind(kind) == OddFiles::Kind::Device)
        QVERIFY(QFile::link(QStringLiteral("/dev/zero"), path));
    else
        odd(kind, path);
    QElapsedTimer clock;
    clock.start();
    sim::SimRomStore store(dir.path());
    QVERIFY(clock.elapsed() < 5000);
    QVERIFY(!store.rom(5, protocol::Series::MF)); // defaults
    QCOMPARE(store.errors().size(), 1);
    QVERIFY2(store.errors().first().contains(said), qPrintable(store.errors().first()));
    QVERIFY(store.errors().first().contains(QLatin1String("rom-id05.json")));
}

// Traces that pass one by one may not pass together: a set holds kMaxSetTraceBytes of them.
void tst_BoundedReaders::stepRunSetBudget()
{
    QTemporaryDir dir;
    const QString json = dir.filePath(QStringLiteral("set.lkruns.json"));
    QVector<tuning::StepRun> runs;
    const int count =
        int(tuning::StepRunFile::kMaxSetTraceBytes / tuning::StepRunFile::kMaxTraceBytes) + 1;
    for (int i = 0; i < count; ++i)
        runs.append(smallRun());
    QCOMPARE(tuning::StepRunFile::save(json, runs), QString());
    QVERIFY(tuning::StepRunFile::load(json));
    // Each trace a valid one of 13.5 MB, under its own bound; together over the set's.
    QByteArray csv = "time_s,value,effort\n";
    for (int i = 0; csv.size() < 13'500'000; ++i)
        csv += QByteArray::number(i * 1e-5, 'f', 6) + ",1.5,0.25\n";
    QVERIFY(csv.size() < tuning::StepRunFile::kMaxTraceBytes);
    QVERIFY(csv.size() * count > tuning::StepRunFile::kMaxSetTraceBytes);
    for (int i = 0; i < count; ++i) {
        QFile f(dir.filePath(QStringLiteral("set.run%1.csv").arg(i + 1)));
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        QCOMPARE(f.write(csv), csv.size());
    }
    tuning::StepRunFileError error;
    QVERIFY(!tuning::StepRunFile::load(json, &error));
    QCOMPARE(error.kind, tuning::StepRunFileError::Kind::TooLarge);
    QCOMPARE(error.path, dir.filePath(QStringLiteral("set.run%1.csv").arg(count)));
}

void tst_BoundedReaders::stepRunSaveRefusesWhatLoadWould()
{
    tuning::StepRun run = smallRun();
    run.number = 4;
    // About 30 bytes a line: past the trace bound.
    const int samples = int(tuning::StepRunFile::kMaxTraceBytes / 20);
    for (int i = 0; i < samples; ++i)
        run.trace.append(1 + i * 1e-4, 360.123456, 1.234567);
    QTemporaryDir dir;
    const QString json = dir.filePath(QStringLiteral("big.lkruns.json"));
    const QString error = tuning::StepRunFile::save(json, {smallRun(), run});
    QVERIFY2(error.contains(QLatin1String("Run 4")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("16.8 MB")), qPrintable(error));
    QVERIFY(!QFile::exists(json));
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("big.run1.csv")))); // nothing written
}

QTEST_GUILESS_MAIN(tst_BoundedReaders)
#include "tst_boundedreaders.moc"
