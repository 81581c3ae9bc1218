// The telemetry CSV schema checked against the real programs: `lkctl monitor` and lkstudio's
// plot export, both reading lksim over a pseudo-terminal, must write exactly the columns that
// docs/CSV.md documents (parsed from its table), so that the document and the programs cannot
// drift apart; and every row must hold one poll round.

#include "E2eUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusSession.h>
#include <plot/PlotExporter.h>
#include <plot/TelemetryStore.h>
#include <protocol/ErrorFlags.h>
#include <record/TelemetryColumns.h>
#include <transport/SerialTransport.h>

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::e2e;
using lk::record::CsvLayout;
using lk::ui::TelemetryChannel;

namespace {

constexpr int kWaitMs = 30000;

/// One row of the signal table of docs/CSV.md.
struct DocColumn {
    QString key, unit;
    int decimals = -1;
};

/// The signal table of docs/CSV.md: the rows of the table whose header starts with
/// "| column | unit | decimals |".
QList<DocColumn> documentedColumns()
{
    QFile file(QStringLiteral(LK_SOURCE_DIR "/docs/CSV.md"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<DocColumn> out;
    bool inTable = false;
    for (const QString &line : QString::fromUtf8(file.readAll()).split('\n')) {
        if (line.startsWith(QLatin1String("| column | unit | decimals |"))) {
            inTable = true;
            continue;
        }
        if (!inTable || line.startsWith(QLatin1String("| ---")))
            continue;
        if (!line.startsWith('|'))
            break;
        const QStringList cells = line.split('|');
        DocColumn c;
        c.key = cells.value(1).trimmed().remove('`');
        c.unit = cells.value(2).trimmed();
        c.decimals = cells.value(3).trimmed().toInt();
        out.append(c);
    }
    return out;
}

QStringList documentedKeys()
{
    QStringList keys;
    for (const DocColumn &c : documentedColumns())
        keys << c.key;
    return keys;
}

/// Header cells of a wide file must be time_s, then id<N>_<documented key>; returns the
/// problem, empty when none.
QString checkWideHeader(const QStringList &header, const QSet<int> &ids)
{
    const QStringList keys = documentedKeys();
    if (header.value(0) != QLatin1String("time_s"))
        return QStringLiteral("first column %1").arg(header.value(0));
    const QRegularExpression cell(QStringLiteral("^id(\\d+)_(.+)$"));
    for (const QString &name : header.mid(1)) {
        const QRegularExpressionMatch m = cell.match(name);
        if (!m.hasMatch() || !ids.contains(m.captured(1).toInt()) || !keys.contains(m.captured(2)))
            return QStringLiteral("undocumented column %1").arg(name);
    }
    return {};
}

/// Header cells of a long file must be time_s, id, then documented keys in the documented
/// order; returns the problem, empty when none.
QString checkLongHeader(const QStringList &header)
{
    const QStringList keys = documentedKeys();
    if (header.mid(0, 2) != QStringList{"time_s", "id"})
        return QStringLiteral("first columns %1").arg(header.mid(0, 2).join(','));
    qsizetype last = -1;
    for (const QString &name : header.mid(2)) {
        const qsizetype at = keys.indexOf(name);
        if (at < 0)
            return QStringLiteral("undocumented column %1").arg(name);
        if (at <= last)
            return QStringLiteral("%1 out of the documented order").arg(name);
        last = at;
    }
    return {};
}

QList<QStringList> parseCsv(const QByteArray &text)
{
    QList<QStringList> rows;
    for (const QByteArray &line : text.split('\n')) {
        if (!line.isEmpty())
            rows.append(QString::fromUtf8(line).split(','));
    }
    return rows;
}

/// Every row has the header's width and a numeric time; wide: one row per round, so times
/// strictly increase; long: one row per drive and round, so (time, id) never repeats.
QString checkRows(const QList<QStringList> &rows, CsvLayout layout)
{
    QSet<QString> seen;
    double previous = -1;
    for (const QStringList &row : rows.mid(1)) {
        bool ok = false;
        const double t = row.value(0).toDouble(&ok);
        if (row.size() != rows.first().size() || !ok)
            return QStringLiteral("bad row %1").arg(row.join(','));
        const QString key = layout == CsvLayout::Wide ? row.at(0) : row.at(0) + ',' + row.at(1);
        if (seen.contains(key) || t < previous)
            return QStringLiteral("round repeated or out of order: %1").arg(row.join(','));
        seen.insert(key);
        previous = t;
    }
    return {};
}

const char kEverything[] = "state2,state1,multi-turn,single-turn,state3,encoder";

} // namespace

class tst_E2eCsv : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void documentMatchesTheColumnTable();
    void documentNamesEveryErrorBit_data();
    void documentNamesEveryErrorBit();
    void lkctlMonitorWritesTheDocumentedSchema_data();
    void lkctlMonitorWritesTheDocumentedSchema();
    void plotExportWritesTheDocumentedSchema_data();
    void plotExportWritesTheDocumentedSchema();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

void tst_E2eCsv::initTestCase()
{
    bus::registerBusMetaTypes();
}

void tst_E2eCsv::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_link = m_dir->filePath(QStringLiteral("lkbus"));
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    // Plus a firmware 2.35 drive: its read_state1 adds bus current and the motor state.
    QStringList args = simArgs(m_link);
    args[1] = simMotors() + QStringLiteral(",5:MS4015@2.35");
    QVERIFY2(m_sim->start(args), qPrintable(m_sim->errorString()));
}

void tst_E2eCsv::cleanup()
{
    m_sim.reset();
    m_dir.reset();
}

void tst_E2eCsv::documentMatchesTheColumnTable()
{
    const QList<DocColumn> doc = documentedColumns();
    const QVector<record::TelemetryColumn> &table = record::TelemetryColumns::all();
    QCOMPARE(doc.size(), table.size());
    for (int i = 0; i < table.size(); ++i) {
        QCOMPARE(doc.at(i).key, QString::fromLatin1(table.at(i).key));
        QCOMPARE(doc.at(i).unit, QString::fromUtf8(table.at(i).unit));
        QCOMPARE(doc.at(i).decimals, table.at(i).decimals);
    }
}

void tst_E2eCsv::documentNamesEveryErrorBit_data()
{
    QTest::addColumn<int>("generation");
    QTest::addColumn<int>("column"); // of the bit table: | bit | value | V2.3 | V2.35 |
    QTest::newRow("V2.3") << int(protocol::Generation::V2_3) << 3;
    QTest::newRow("V2.35") << int(protocol::Generation::V2_35) << 4;
}

// error_state's bits by generation: each bit the protocol names, by its words, in the
// document's bit table; the others "unused".
void tst_E2eCsv::documentNamesEveryErrorBit()
{
    QFETCH(int, generation);
    QFETCH(int, column);
    QFile file(QStringLiteral(LK_SOURCE_DIR "/docs/CSV.md"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QMap<int, QString> documented; // bit -> cell
    bool inTable = false;
    for (const QString &line : QString::fromUtf8(file.readAll()).split('\n')) {
        if (line.startsWith(QLatin1String("| bit | value |"))) {
            inTable = true;
        } else if (inTable && line.startsWith(QLatin1String("| ---"))) {
            continue;
        } else if (inTable && line.startsWith('|')) {
            const QStringList cells = line.split('|');
            documented.insert(cells.value(1).trimmed().toInt(), cells.value(column).trimmed());
        } else if (inTable) {
            break;
        }
    }
    QCOMPARE(documented.keys(), (QList<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    const auto gen = protocol::Generation(generation);
    for (int bit = 0; bit < 8; ++bit) {
        const QVector<protocol::ErrorFlag> set = protocol::ErrorFlags::set(quint8(1u << bit), gen);
        const QString expected =
            set.isEmpty() ? QStringLiteral("unused") : QString::fromLatin1(set.first().text);
        QVERIFY2(documented.value(bit).startsWith(expected),
                 qPrintable(QStringLiteral("bit %1: documented \"%2\", the protocol says \"%3\"")
                                .arg(bit)
                                .arg(documented.value(bit), expected)));
    }
}

void tst_E2eCsv::lkctlMonitorWritesTheDocumentedSchema_data()
{
    QTest::addColumn<CsvLayout>("layout");
    QTest::newRow("wide") << CsvLayout::Wide;
    QTest::newRow("long") << CsvLayout::Long;
}

void tst_E2eCsv::lkctlMonitorWritesTheDocumentedSchema()
{
    QFETCH(CsvLayout, layout);
    const CtlResult r =
        lkctl({"monitor", "3", "5", "17", "32", "--port", m_link, "--what", kEverything, "--rate",
               "0", "--count", "12", "--csv-layout", record::TelemetryCsv::layoutName(layout)});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<QStringList> rows = parseCsv(r.out);
    QCOMPARE(rows.size(), 13);
    const QStringList header = rows.first();
    const QString problem = layout == CsvLayout::Wide ? checkWideHeader(header, {3, 5, 17, 32})
                                                      : checkLongHeader(header);
    QVERIFY2(problem.isEmpty(), qPrintable(problem + ": " + header.join(',')));
    QVERIFY2(checkRows(rows, layout).isEmpty(), qPrintable(checkRows(rows, layout)));
    // Everything polled: every documented column is there (power for the MS drives 5 and 17,
    // iq and phase currents for the others, bus current and motor state for drive 5).
    QSet<QString> keys;
    for (const QString &name : header.mid(1))
        keys.insert(name.section('_', layout == CsvLayout::Wide ? 1 : 0));
    keys.remove(QStringLiteral("id"));
    // The commanded_* columns come only from another master's requests (lkctl listen), never
    // from a poll.
    QStringList documented = documentedKeys();
    documented.removeIf([](const QString &k) { return k.startsWith(QLatin1String("commanded_")); });
    QCOMPARE(keys, QSet<QString>(documented.begin(), documented.end()));
}

void tst_E2eCsv::plotExportWritesTheDocumentedSchema_data()
{
    lkctlMonitorWritesTheDocumentedSchema_data();
}

void tst_E2eCsv::plotExportWritesTheDocumentedSchema()
{
    QFETCH(CsvLayout, layout);
    // lkstudio's path: BusSession over a real serial port, telemetry into a TelemetryStore,
    // PlotExporter writes the plotted traces.
    bus::BusSession session;
    transport::SerialSettings port;
    port.portName = m_link;
    bus::BusConfig config;
    config.minMarginMs = 30; // functional, not timing: a loaded machine must not time out
    config.initialMarginMs = 100;
    session.open(transport::SerialTransport::factory(port), 115200, config);
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), kWaitMs);
    session.setSeries(3, protocol::Series::MF);
    session.setSeries(17, protocol::Series::MS);
    session.setSeries(32, protocol::Series::MG);
    ui::TelemetryStore store;
    QObject::connect(&session, &bus::BusSession::telemetryReceived, &store,
                     &ui::TelemetryStore::append);
    bus::PollPlan plan;
    plan.ids = {3, 17, 32};
    plan.commands = {protocol::Command::ReadState2, protocol::Command::ReadState1,
                     protocol::Command::ReadMultiTurn, protocol::Command::ReadSingleTurn,
                     protocol::Command::ReadState3};
    plan.rateHz = 0;
    session.startPolling(plan);
    QTRY_VERIFY_WITH_TIMEOUT(store.count(32, TelemetryChannel::PhaseC) >= 10, kWaitMs);
    session.stopPolling();

    QVector<ui::PlotTrace> traces;
    for (int id : {3, 17, 32}) {
        for (int c = 0; c < ui::kTelemetryChannelCount; ++c) {
            const auto channel = TelemetryChannel(c);
            if (store.ring(id, channel))
                traces.append({id, channel, id == 17 && channel == TelemetryChannel::Torque});
        }
    }
    const QString path = m_dir->filePath(QStringLiteral("plot.csv"));
    constexpr double kInf = std::numeric_limits<double>::infinity();
    QCOMPARE(ui::PlotExporter::exportCsv(store, traces, {-kInf, kInf}, path, layout), QString());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QStringList> rows = parseCsv(file.readAll());
    QVERIFY(rows.size() > 10);
    const QStringList header = rows.first();
    const QString problem =
        layout == CsvLayout::Wide ? checkWideHeader(header, {3, 17, 32}) : checkLongHeader(header);
    QVERIFY2(problem.isEmpty(), qPrintable(problem + ": " + header.join(',')));
    QVERIFY2(checkRows(rows, layout).isEmpty(), qPrintable(checkRows(rows, layout)));
    if (layout == CsvLayout::Wide) {
        QVERIFY(header.contains("id17_power") && header.contains("id3_iq_a"));
        QVERIFY(header.contains("id32_ic_a") && header.contains("id3_multi_turn_deg"));
    }
}

QTEST_GUILESS_MAIN(tst_E2eCsv)
#include "tst_e2ecsv.moc"
