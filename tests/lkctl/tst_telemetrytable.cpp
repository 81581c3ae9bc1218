// The one table of telemetry values (bus::TelemetryFieldInfo) against everything that reads
// it: every TelemetryField has its rows, keys are unique, each key reaches the CSV writer's
// header and lkctl monitor's, V2.35-only rows are the ones only a V2.35 reply carries, and
// TelemetrySample::merge walks every row. Here (not in tests/core) because it also checks
// lkctl's MonitorTable.

#include <MonitorTable.h>

#include <bus/TelemetryFieldInfo.h>
#include <record/TelemetryCsv.h>

#include <QtCore/QMetaEnum>
#include <QtTest/QtTest>

using lk::bus::kTelemetryFieldCount;
using lk::bus::TelemetryField;
using lk::bus::TelemetryFieldInfo;
using lk::bus::TelemetryFields;
using lk::bus::TelemetrySample;
using lk::lkctl::MonitorFormat;
using lk::lkctl::MonitorTable;
using lk::protocol::Command;
using lk::protocol::Series;
using lk::record::TelemetryCsv;

namespace {

const QVector<Command> kPolled{Command::ReadState1,     Command::ReadState2,
                               Command::ReadState3,     Command::ReadMultiTurn,
                               Command::ReadSingleTurn, Command::ReadEncoder};

QStringList headerCells(const QByteArray &header)
{
    return QString::fromLatin1(header.trimmed()).split(QLatin1Char(','));
}

QVector<int> allColumns()
{
    QVector<int> columns;
    for (int i = 0; i < TelemetryFieldInfo::all().size(); ++i)
        columns.append(i);
    return columns;
}

/// A sample carrying every field, each value derived from `base` (motorOn: its parity).
TelemetrySample everything(int base)
{
    TelemetrySample s;
    s.fields = TelemetryFields::fromInt((1u << kTelemetryFieldCount) - 1);
    s.temperatureC = base + 1;
    s.iqA = base + 2.5;
    s.power = base + 3;
    s.speedDps = base + 4.5;
    s.encoder = base + 5;
    s.voltageV = base + 6.5;
    s.errorState = base + 7;
    s.multiTurnDeg = base + 8.5;
    s.singleTurnDeg = base + 9.5;
    s.iaA = base + 10.5;
    s.ibA = base + 11.5;
    s.icA = base + 12.5;
    s.busCurrentA = base + 13.5;
    s.motorOn = base % 2 != 0;
    s.commandedIqA = base + 14.5;
    s.commandedPower = base + 15;
    s.commandedSpeedDps = base + 16.5;
    s.commandedAngleDeg = base + 17.5;
    return s;
}

} // namespace

class tst_TelemetryTable : public QObject {
    Q_OBJECT
private slots:
    void everyFieldHasItsRows();
    void keysAreUniqueAndNamed();
    void csvHeaderNamesEveryKey();
    void monitorHeaderNamesEveryKey_data();
    void monitorHeaderNamesEveryKey();
    void v235OnlyRowsAreTheV235Replies();
    void mergeTakesWhatTheNewerCarries_data();
    void mergeTakesWhatTheNewerCarries();
};

void tst_TelemetryTable::everyFieldHasItsRows()
{
    const QMetaEnum fields = QMetaEnum::fromType<TelemetryField>();
    QCOMPARE(fields.keyCount(), kTelemetryFieldCount);
    const QVector<TelemetryFieldInfo> &rows = TelemetryFieldInfo::all();
    int covered = 0;
    for (int i = 0; i < fields.keyCount(); ++i) {
        QCOMPARE(fields.value(i), 1 << i); // one bit each, none skipped
        const auto field = TelemetryField(fields.value(i));
        int count = 0;
        for (const TelemetryFieldInfo &row : rows)
            count += row.field == field ? 1 : 0;
        // One row a field; the phase currents come as three values of one reply.
        QVERIFY2(count == (field == TelemetryField::PhaseCurrents ? 3 : 1), fields.key(i));
        covered += count;
    }
    QCOMPARE(covered, rows.size()); // no row names a field outside the enum
}

void tst_TelemetryTable::keysAreUniqueAndNamed()
{
    const QVector<TelemetryFieldInfo> &rows = TelemetryFieldInfo::all();
    QSet<QString> keys, labels;
    for (int i = 0; i < rows.size(); ++i) {
        const TelemetryFieldInfo &row = rows.at(i);
        const QString key = QString::fromLatin1(row.key);
        QVERIFY2(!keys.contains(key), row.key);
        keys.insert(key);
        QCOMPARE(TelemetryFieldInfo::indexOf(key), std::optional<int>(i));
        QVERIFY2(qstrlen(row.unit) > 0, row.key);
        QVERIFY2(qstrlen(row.label) > 0 && !labels.contains(QLatin1String(row.label)), row.key);
        labels.insert(QLatin1String(row.label));
        QVERIFY2(row.decimals >= 0 && row.displayDecimals >= row.decimals, row.key);
    }
    QCOMPARE(TelemetryFieldInfo::indexOf(QStringLiteral("no_such_key")), std::nullopt);
}

void tst_TelemetryTable::csvHeaderNamesEveryKey()
{
    const QStringList longHeader = headerCells(TelemetryCsv::longLayout(allColumns()).header());
    QVector<TelemetryCsv::Cell> cells;
    for (int column : allColumns())
        cells.append({3, column});
    const QStringList wideHeader = headerCells(TelemetryCsv::wide(cells).header());
    QCOMPARE(longHeader.size(), TelemetryFieldInfo::all().size() + 2); // time_s, id
    QCOMPARE(wideHeader.size(), TelemetryFieldInfo::all().size() + 1); // time_s
    for (const TelemetryFieldInfo &row : TelemetryFieldInfo::all()) {
        QVERIFY2(longHeader.contains(QLatin1String(row.key)), row.key);
        QVERIFY2(wideHeader.contains(QStringLiteral("id3_") + QLatin1String(row.key)), row.key);
    }
}

void tst_TelemetryTable::monitorHeaderNamesEveryKey_data()
{
    QTest::addColumn<MonitorFormat>("format");
    QTest::newRow("wide") << MonitorFormat::CsvWide;
    QTest::newRow("long") << MonitorFormat::CsvLong;
}

void tst_TelemetryTable::monitorHeaderNamesEveryKey()
{
    // Everything polled from an MF drive on firmware 2.35 and an MS drive: every value a
    // drive can report has its column.
    QFETCH(MonitorFormat, format);
    const MonitorTable table(kPolled, {{3, Series::MF}, {17, Series::MS}}, format, {3});
    QSet<QString> keys;
    for (const QString &cell : headerCells(table.header()).mid(1)) {
        if (cell != QLatin1String("id"))
            keys.insert(format == MonitorFormat::CsvWide ? cell.section(QLatin1Char('_'), 1)
                                                         : cell);
    }
    // What another master commands (lkctl listen) is no poll's: those columns are not here.
    int commanded = 0;
    for (const TelemetryFieldInfo &row : TelemetryFieldInfo::all()) {
        if (TelemetrySample::commandedFields().testFlag(row.field)) {
            QVERIFY2(!keys.contains(QLatin1String(row.key)), row.key);
            ++commanded;
            continue;
        }
        QVERIFY2(keys.contains(QLatin1String(row.key)), row.key);
    }
    QCOMPARE(commanded, 8);
    QCOMPARE(keys.size(), TelemetryFieldInfo::all().size() - commanded);
}

void tst_TelemetryTable::v235OnlyRowsAreTheV235Replies()
{
    TelemetryFields v23, v235;
    for (Command c : kPolled) {
        for (std::optional<Series> series :
             {std::optional<Series>(), std::optional(Series::MS), std::optional(Series::MF)}) {
            v23 |= TelemetrySample::fieldsOf(c, series, false);
            v235 |= TelemetrySample::fieldsOf(c, series, true);
        }
    }
    for (const TelemetryFieldInfo &row : TelemetryFieldInfo::all()) {
        if (TelemetrySample::commandedFields().testFlag(row.field)) {
            QVERIFY2(!v23.testFlag(row.field) && !v235.testFlag(row.field), row.key);
            continue; // no reply carries a commanded value: requests do (fromRequest)
        }
        QVERIFY2(v235.testFlag(row.field), row.key); // a polled reply carries every row
        QVERIFY2(row.v235Only == !v23.testFlag(row.field), row.key);
    }
}

void tst_TelemetryTable::mergeTakesWhatTheNewerCarries_data()
{
    QTest::addColumn<int>("field");
    const QMetaEnum fields = QMetaEnum::fromType<TelemetryField>();
    for (int i = 0; i < fields.keyCount(); ++i)
        QTest::newRow(fields.key(i)) << fields.value(i);
}

void tst_TelemetryTable::mergeTakesWhatTheNewerCarries()
{
    QFETCH(int, field);
    const auto carried = TelemetryField(field);
    const TelemetrySample older = everything(100);
    TelemetrySample newer = everything(201);
    newer.fields = carried;
    newer.id = 7;
    newer.time = 2.5;
    newer.cycle = 9;
    newer.cycleTime = 2.25;
    newer.source = Command::ReadEncoder;

    TelemetrySample merged = older;
    merged.merge(newer);
    QCOMPARE(merged.fields, older.fields | carried);
    QCOMPARE(merged.id, 7);
    QCOMPARE(merged.time, 2.5);
    QCOMPARE(merged.cycle, quint64(9));
    QCOMPARE(merged.cycleTime, 2.25);
    QCOMPARE(merged.source, Command::ReadEncoder);
    for (const TelemetryFieldInfo &row : TelemetryFieldInfo::all()) {
        const TelemetrySample &from = row.field == carried ? newer : older;
        QVERIFY2(row.value(merged) == row.value(from), row.key);
    }
    // Into an empty sample: only what the newer carries.
    TelemetrySample fresh;
    fresh.merge(newer);
    QCOMPARE(fresh.fields, TelemetryFields(carried));
}

QTEST_APPLESS_MAIN(tst_TelemetryTable)
#include "tst_telemetrytable.moc"
