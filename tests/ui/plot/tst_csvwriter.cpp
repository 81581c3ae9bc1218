#include <record/CsvWriter.h>
#include <record/PollCycleIndex.h>
#include <record/TelemetryColumns.h>
#include <record/TelemetryCsv.h>

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <csignal>
#include <limits>

#include <sys/resource.h>

using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::record::CsvWriter;
using lk::record::CycleValues;
using lk::record::PollCycleIndex;
using lk::record::TelemetryColumns;
using lk::record::TelemetryCsv;

namespace {

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<missing>");
}

/// Writes `header` then `rows` lines of "i,i" through a CsvWriter; returns its error text.
QString writeNumbered(const QString &path, int rows)
{
    CsvWriter writer(path);
    if (QString error = writer.begin("time_s,v\n"); !error.isEmpty())
        return error;
    for (int i = 0; i < rows; ++i)
        writer.write(CsvWriter::formatNumber(i * 0.001, 6) + ',' + QByteArray::number(i) + '\n');
    return writer.finish();
}

int column(const char *key)
{
    return TelemetryColumns::indexOf(QLatin1String(key)).value();
}

/// One drive's values of a round: the given columns set, every other one empty.
QVector<double> values(std::initializer_list<std::pair<const char *, double>> cells)
{
    QVector<double> v = TelemetryColumns::empty();
    for (const auto &[key, value] : cells)
        v[column(key)] = value;
    return v;
}

} // namespace

class tst_CsvWriter : public QObject {
    Q_OBJECT
private slots:
    void formatsNumbers_data();
    void formatsNumbers();
    void columnNamesFollowTheCliContract();
    void wideLayout();
    void longLayout();
    void pollCycleIndexFindsRounds();
    void largeFileRoundTrips();
    void reportsUnwritablePath_data();
    void reportsUnwritablePath();
    void abandonedWriterLeavesNoFile();
    void failedWriteKeepsOldFile_data();
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

void tst_CsvWriter::columnNamesFollowTheCliContract()
{
    // snake_case with the unit as suffix, except the unitless integers of CLI.md.
    const QSet<QString> unitless{"error_state", "power",           "encoder",
                                 "motor_on",    "commanded_power", "commanded_direction"};
    const QRegularExpression withUnit("^[a-z]+(_[a-z]+)*_(c|v|a|dps|deg)$");
    QSet<QString> seen;
    for (const auto &c : TelemetryColumns::all()) {
        const QString key = QLatin1String(c.key);
        QVERIFY2(unitless.contains(key) || withUnit.match(key).hasMatch(), c.key);
        QVERIFY2(!seen.contains(key), c.key);
        seen.insert(key);
    }
    QCOMPARE(TelemetryColumns::of(TelemetryField::PhaseCurrents),
             (QVector<int>{column("ia_a"), column("ib_a"), column("ic_a")}));
}

void tst_CsvWriter::wideLayout()
{
    const TelemetryCsv csv =
        TelemetryCsv::wide({{3, column("iq_a")}, {3, column("speed_dps")}, {17, column("power")}});
    QCOMPARE(csv.header(), QByteArray("time_s,id3_iq_a,id3_speed_dps,id17_power\n"));
    CycleValues round;
    round.time = 1.5;
    round.drives[3] = values({{"iq_a", -0.25}, {"speed_dps", 360}, {"encoder", 7}});
    QCOMPARE(csv.rows(round), QList<QByteArray>{"1.500000,-0.2500,360,\n"}); // 17: nothing
    round.drives[17] = values({{"power", -300}});
    QCOMPARE(csv.rows(round), QList<QByteArray>{"1.500000,-0.2500,360,-300\n"});
    CycleValues unplotted; // only values of columns the file does not have: no row
    unplotted.drives[3] = values({{"voltage_v", 24}});
    QCOMPARE(csv.rows(unplotted), QList<QByteArray>{});
}

void tst_CsvWriter::longLayout()
{
    const TelemetryCsv csv = TelemetryCsv::longLayout(
        {column("speed_dps"), column("temperature_c"), column("speed_dps"), column("iq_a")});
    QCOMPARE(csv.header(), QByteArray("time_s,id,temperature_c,iq_a,speed_dps\n"));
    CycleValues round;
    round.time = 0.25;
    round.drives[17] = values({{"temperature_c", 31}});
    round.drives[3] = values({{"iq_a", 0.0161}, {"speed_dps", -12}});
    QCOMPARE(csv.rows(round),
             (QList<QByteArray>{"0.250000,3,,0.0161,-12\n", "0.250000,17,31,,\n"}));
    QCOMPARE(TelemetryCsv::layoutFromName("long"), lk::record::CsvLayout::Long);
    QCOMPARE(TelemetryCsv::layoutFromName("wide"), lk::record::CsvLayout::Wide);
    QVERIFY(!TelemetryCsv::layoutFromName("Wide"));
}

void tst_CsvWriter::pollCycleIndexFindsRounds()
{
    PollCycleIndex index(2); // at most 2 samples per polled command and drive
    const auto sample = [](int id, lk::protocol::Command c, quint64 cycle, double t) {
        TelemetrySample s;
        s.id = id;
        s.source = c;
        s.cycle = cycle;
        s.cycleTime = cycle * 0.1;
        s.time = t;
        s.fields = TelemetryField::Temperature;
        return s;
    };
    using lk::protocol::Command;
    index.add(sample(3, Command::ReadState2, 1, 0.101));
    index.add(sample(3, Command::ReadState1, 1, 0.102));
    index.add(sample(3, Command::ReadState2, 0, 0.150)); // an operator's read: no round
    index.add(sample(3, Command::ReadState2, 2, 0.201));
    QCOMPARE(index.find(3, 0.102)->cycle, quint64(1));
    QCOMPARE(index.find(3, 0.102)->time, 0.1);
    QCOMPARE(index.find(3, 0.201)->cycle, quint64(2));
    QVERIFY(!index.find(3, 0.150));
    QVERIFY(!index.find(4, 0.101));
    index.add(sample(3, Command::ReadState1, 2, 0.202));
    index.add(sample(3, Command::ReadState2, 3, 0.301)); // 5 > 2 x 2 commands: oldest goes
    QVERIFY(!index.find(3, 0.101));
    QCOMPARE(index.find(3, 0.301)->cycle, quint64(3));
    index.clear();
    QVERIFY(!index.find(3, 0.301));
}

void tst_CsvWriter::largeFileRoundTrips()
{
    // Many buffer flushes: every row must arrive once and in order.
    QTemporaryDir dir;
    const QString path = dir.filePath("big.csv");
    QCOMPARE(writeNumbered(path, 200000), QString());
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
    const QString error = writeNumbered(path, 1);
    QVERIFY2(!error.isEmpty(), "an unwritable path must be reported");
}

void tst_CsvWriter::abandonedWriterLeavesNoFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("half.csv");
    {
        CsvWriter writer(path);
        QCOMPARE(writer.begin("time_s,v\n"), QString());
        writer.write("1.000000,2\n");
    } // destroyed without finish(): e.g. an exception or an early return
    QVERIFY(!QFile::exists(path));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{});
}

void tst_CsvWriter::failedWriteKeepsOldFile_data()
{
    QTest::addColumn<int>("limit");
    QTest::addColumn<int>("rows");
    QTest::newRow("disk fills mid-file") << 64 * 1024 << 100000;
    // A small file stays in QSaveFile's buffer until commit(), whose own flush failure
    // Qt 6.4 does not stop from renaming the cut file into place.
    QTest::newRow("disk full at the last flush") << 32 << 20;
}

void tst_CsvWriter::failedWriteKeepsOldFile()
{
    // A disk that fills up, simulated with a file size limit (works as root too).
    QFETCH(int, limit);
    QFETCH(int, rows);
    QTemporaryDir dir;
    const QString path = dir.filePath("keep.csv");
    {
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("old content\n");
    }
    rlimit saved{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &saved), 0);
    rlimit small = saved;
    small.rlim_cur = rlim_t(limit);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // EFBIG instead of a signal
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
    const QString error = writeNumbered(path, rows);
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, oldHandler);
    QVERIFY2(!error.isEmpty(), "a failed write must be reported");
    QCOMPARE(readAll(path), QByteArray("old content\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"keep.csv"});
}

QTEST_APPLESS_MAIN(tst_CsvWriter)
#include "tst_csvwriter.moc"
