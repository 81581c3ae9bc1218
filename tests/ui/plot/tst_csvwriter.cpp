#include <record/CsvWriter.h>

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <csignal>
#include <limits>

#include <sys/resource.h>

using lk::record::CsvSeries;
using lk::record::CsvWriter;

namespace {

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<missing>");
}

} // namespace

class tst_CsvWriter : public QObject {
    Q_OBJECT
private slots:
    void formatsNumbers_data();
    void formatsNumbers();
    void quotesHeaderCells_data();
    void quotesHeaderCells();
    void alignsSeriesByTimestamp();
    void writesHeaderOnlyWhenNoPoints();
    void largeFileRoundTrips();
    void reportsUnwritablePath_data();
    void reportsUnwritablePath();
    void abandonedWriterLeavesNoFile();
    void failedWriteKeepsOldFile();
};

void tst_CsvWriter::formatsNumbers_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("decimals");
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("time, 6 decimals") << 12.3456789 << 6 << QByteArray("12.345679");
    QTest::newRow("integer") << 8000.0 << 0 << QByteArray("8000");
    QTest::newRow("negative") << -0.515625 << 4 << QByteArray("-0.5156");
    QTest::newRow("negative zero") << -0.0 << 2 << QByteArray("0.00");
    QTest::newRow("rounds to zero") << -0.0001 << 2 << QByteArray("0.00");
    QTest::newRow("large angle") << 123456789.01 << 2 << QByteArray("123456789.01");
    QTest::newRow("NaN is empty") << std::numeric_limits<double>::quiet_NaN() << 3 << QByteArray();
    QTest::newRow("infinity is empty")
        << std::numeric_limits<double>::infinity() << 3 << QByteArray();
}

void tst_CsvWriter::formatsNumbers()
{
    QFETCH(double, value);
    QFETCH(int, decimals);
    QFETCH(QByteArray, text);
    QCOMPARE(CsvWriter::formatNumber(value, decimals), text);
}

void tst_CsvWriter::quotesHeaderCells_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QByteArray>("cell");
    QTest::newRow("plain") << "id3_iq_a" << QByteArray("id3_iq_a");
    QTest::newRow("comma") << "a,b" << QByteArray("\"a,b\"");
    QTest::newRow("quote") << "say \"hi\"" << QByteArray("\"say \"\"hi\"\"\"");
    QTest::newRow("newline") << "a\nb" << QByteArray("\"a\nb\"");
    QTest::newRow("utf-8") << QStringLiteral("温度") << QStringLiteral("温度").toUtf8();
}

void tst_CsvWriter::quotesHeaderCells()
{
    QFETCH(QString, field);
    QFETCH(QByteArray, cell);
    QCOMPARE(CsvWriter::quoteField(field), cell);
}

void tst_CsvWriter::alignsSeriesByTimestamp()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("out.csv");
    // Drive 3: iq and speed from the same replies (shared times); drive 4 polled in between.
    const QVector<CsvSeries> series{
        {"id3_iq_a", 4, {0.001, 0.003}, {0.5, -1.25}},
        {"id3_speed_dps", 2, {0.001, 0.003}, {120, 121.5}},
        {"id4_iq_a", 4, {0.002, 0.003, 0.004}, {2, 3, 4}},
    };
    QCOMPARE(CsvWriter::writeAligned(path, series), QString());
    QCOMPARE(readAll(path), QByteArray("time_s,id3_iq_a,id3_speed_dps,id4_iq_a\n"
                                       "0.001000,0.5000,120.00,\n"
                                       "0.002000,,,2.0000\n"
                                       "0.003000,-1.2500,121.50,3.0000\n"
                                       "0.004000,,,4.0000\n"));
}

void tst_CsvWriter::writesHeaderOnlyWhenNoPoints()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("empty.csv");
    QCOMPARE(CsvWriter::writeAligned(path, {{"id1_speed_dps", 2, {}, {}}}), QString());
    QCOMPARE(readAll(path), QByteArray("time_s,id1_speed_dps\n"));
}

void tst_CsvWriter::largeFileRoundTrips()
{
    // Many buffer flushes: every row must arrive once and in order.
    QTemporaryDir dir;
    const QString path = dir.filePath("big.csv");
    CsvSeries s{"v", 0, {}, {}};
    for (int i = 0; i < 200000; ++i) {
        s.times.append(i * 0.001);
        s.values.append(i);
    }
    QCOMPARE(CsvWriter::writeAligned(path, {s}), QString());
    const QList<QByteArray> lines = readAll(path).split('\n');
    QCOMPARE(lines.size(), 200000 + 2); // header + rows + the empty piece after the last \n
    QCOMPARE(lines.at(1), QByteArray("0.000000,0"));
    QCOMPARE(lines.at(200000), QByteArray("199.999000,199999"));
}

void tst_CsvWriter::reportsUnwritablePath_data()
{
    QTest::addColumn<QString>("path");
    QTest::newRow("missing directory") << "/nonexistent-lk-dir/x/out.csv";
    QTest::newRow("a directory") << QDir::tempPath();
}

void tst_CsvWriter::reportsUnwritablePath()
{
    QFETCH(QString, path);
    const QString error = CsvWriter::writeAligned(path, {{"a", 1, {1}, {2}}});
    QVERIFY2(!error.isEmpty(), "an unwritable path must be reported");
}

void tst_CsvWriter::abandonedWriterLeavesNoFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("half.csv");
    {
        CsvWriter writer(path);
        QCOMPARE(writer.begin({"time_s", "v"}, {6, 2}), QString());
        const double row[] = {1, 2};
        writer.writeRow(row, 2);
    } // destroyed without finish(): e.g. an exception or an early return
    QVERIFY(!QFile::exists(path));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{});
}

void tst_CsvWriter::failedWriteKeepsOldFile()
{
    // A disk that fills up mid-file, simulated with a file size limit (works as root too).
    QTemporaryDir dir;
    const QString path = dir.filePath("keep.csv");
    {
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("old content\n");
    }
    CsvSeries s{"v", 0, {}, {}};
    for (int i = 0; i < 100000; ++i) {
        s.times.append(i);
        s.values.append(i);
    }
    rlimit saved{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &saved), 0);
    rlimit small = saved;
    small.rlim_cur = 64 * 1024;
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // EFBIG instead of a signal
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
    const QString error = CsvWriter::writeAligned(path, {s});
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, oldHandler);
    QVERIFY2(!error.isEmpty(), "a failed write must be reported");
    QCOMPARE(readAll(path), QByteArray("old content\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"keep.csv"});
}

QTEST_APPLESS_MAIN(tst_CsvWriter)
#include "tst_csvwriter.moc"
