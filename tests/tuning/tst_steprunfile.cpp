// Run files: a set of step runs saves to NAME.lkruns.json plus one CSV per trace and loads
// back unchanged; every kind of bad file is refused with the file and the key or line named.

#include <tuning/StepRunFile.h>
#include <tuning/StepRunJson.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <cmath>
#include <functional>

using namespace lk::tuning;
using Kind = StepRunFileError::Kind;

Q_DECLARE_METATYPE(lk::tuning::StepRunFileError::Kind)

namespace {

/// Speed step 0 -> 360 dps on an MF drive (V2.3), current on every sample, clock starting at
/// a host timestamp far from 0.
StepRun speedRun()
{
    StepRun run;
    run.number = 1;
    run.label = QStringLiteral("Kp 50, \"baseline\" 基线");
    run.ranAt = QDateTime(QDate(2026, 11, 23), QTime(17, 42, 38, 123), Qt::UTC);
    run.driveId = 3;
    run.series = "MF";
    run.model = "MF4015";
    run.generation = "v2.3";
    run.spec = {StepLoop::Speed, 0, 360, 0.5, 1};
    run.gains = QJsonObject{{"angle_kp", 100}, {"angle_ki", 100}, {"speed_kp", 50},
                            {"speed_ki", 40},  {"iq_kp", 50},     {"iq_ki", 50}};
    run.ramps = QJsonObject{{"accel_dps2", 20000}};
    run.effortLimit = 33;
    const double t0 = 81234.5;
    for (int i = 0; i <= 120; ++i) {
        const double t = t0 + i * 0.004;
        const double s = t - (t0 + 0.04);
        run.trace.append(t, s < 0 ? 0 : 360 * (1 - std::exp(-s / 0.05)),
                         s < 0 ? 0.0 : 3 * std::exp(-s / 0.05));
    }
    run.trace.edges = {StepEdge{t0 + 0.04, 0, 360}};
    return run;
}

/// Position square 36000 <-> 36090 deg on an MS drive (V2.35, power), every other sample
/// without effort (0x92 angle replies), no effort limit known.
StepRun positionRun()
{
    StepRun run;
    run.number = 7;
    run.ranAt = QDateTime(QDate(2026, 11, 16), QTime(9, 0), Qt::UTC);
    run.driveId = 1;
    run.series = "MS";
    run.model = "MS4015";
    run.generation = "v2.35";
    run.spec = {StepLoop::Position, 36000, 36090, 0.3, 2};
    run.gains = QJsonObject{{"angle_kp", 100}, {"angle_ki", 100}, {"angle_kd", 0},
                            {"speed_kp", 50},  {"speed_ki", 40},  {"speed_kd", 0},
                            {"iq_kp", 50},     {"iq_ki", 50},     {"iq_kd", 0}};
    run.ramps = QJsonObject{{"current_ramp", 0}, {"speed_ramp_dps2", 20000}};
    run.trace.effortIsPower = true;
    const double t0 = 100.0;
    run.trace.edges = {StepEdge{t0 + 0.1, 36000, 36090}, StepEdge{t0 + 0.4013, 36090, 36000},
                       StepEdge{t0 + 0.7021, 36000, 36090}, StepEdge{t0 + 1.0037, 36090, 36000}};
    for (int i = 0; i <= 260; ++i) {
        const double t = t0 + i * 0.005;
        double v = 36000;
        for (const StepEdge &e : run.trace.edges)
            if (t >= e.time)
                v += e.amplitude() * (1 - std::exp(-(t - e.time) / 0.03));
        run.trace.append(t, v, i % 2 ? StepTrace::missing() : -150.0 + i);
    }
    return run;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return f.readAll();
}

void writeAll(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        qFatal("cannot write %s", qPrintable(path));
    f.write(bytes);
}

void compareMetric(const Metric &a, const Metric &b, const char *name)
{
    QVERIFY2(a.gap == b.gap, name);
    QVERIFY2(a.known() == b.known(), name);
    if (a.known())
        QVERIFY2(std::abs(*a.value - *b.value) < 1e-5, name);
}

} // namespace

class tst_StepRunFile : public QObject {
    Q_OBJECT
private slots:
    void layout();
    void roundTrip();
    void refused_data();
    void refused();
    void equalTimesLoad();
    void missingJson();
    void missingTrace();
    void saveFailureNamesTheFile();
    void traceFileNames();

private:
    QTemporaryDir m_dir;
};

void tst_StepRunFile::layout()
{
    const QString json = m_dir.filePath("bench.lkruns.json");
    QCOMPARE(StepRunFile::save(json, {speedRun(), positionRun()}), QString());
    QVERIFY(QFile::exists(m_dir.filePath("bench.run1.csv")));
    QVERIFY(QFile::exists(m_dir.filePath("bench.run2.csv")));
    const QJsonObject root = QJsonDocument::fromJson(readAll(json)).object();
    QCOMPARE(root.value("format").toString(), QString("lkstudio-step-runs"));
    QCOMPARE(root.value("version").toInt(), 1);
    const QJsonObject run = root.value("runs").toArray().at(1).toObject();
    QCOMPARE(run.value("trace").toString(), QString("bench.run2.csv"));
    QCOMPARE(run.value("ran_at").toString(), QString("2026-11-16T09:00:00.000Z"));
    QCOMPARE(run.value("effort").toString(), QString("power"));
    QVERIFY(run.value("effort_limit").isNull());
    QCOMPARE(run.value("edges").toArray().at(0).toObject().value("time_s").toDouble(), 0.0);
    QCOMPARE(run.value("metrics").toObject().value("saturated_s_why").toString(),
             QString("no_limit"));

    const QList<QByteArray> lines = readAll(m_dir.filePath("bench.run2.csv")).split('\n');
    QCOMPARE(lines.at(0), QByteArray("time_s,value,effort"));
    QCOMPARE(lines.at(1), QByteArray("-0.100000,36000.000000,-150.000000")); // before the edge
    QCOMPARE(lines.at(2), QByteArray("-0.095000,36000.000000,")); // no effort: empty, not 0
    QCOMPARE(lines.size(), 1 + 261 + 1);                          // header, samples, final ""
}

void tst_StepRunFile::roundTrip()
{
    const QVector<StepRun> saved = {speedRun(), positionRun()};
    const QString json = m_dir.filePath("trip.lkruns.json");
    QCOMPARE(StepRunFile::save(json, saved), QString());
    StepRunFileError error;
    const std::optional<QVector<StepRun>> loaded = StepRunFile::load(json, &error);
    QVERIFY2(loaded, qPrintable(error.toString()));
    QCOMPARE(loaded->size(), 2);
    for (int r = 0; r < 2; ++r) {
        const StepRun &a = saved[r];
        const StepRun &b = loaded->at(r);
        QCOMPARE(b.number, a.number);
        QCOMPARE(b.label, a.label);
        QCOMPARE(b.ranAt, a.ranAt);
        QCOMPARE(b.ranAt.timeSpec(), Qt::UTC);
        QCOMPARE(b.driveId, a.driveId);
        QCOMPARE(b.series, a.series);
        QCOMPARE(b.model, a.model);
        QCOMPARE(b.generation, a.generation);
        QCOMPARE(b.spec.loop, a.spec.loop);
        QCOMPARE(b.spec.from, a.spec.from);
        QCOMPARE(b.spec.to, a.spec.to);
        QCOMPARE(b.spec.durationS, a.spec.durationS);
        QCOMPARE(b.spec.periods, a.spec.periods);
        QCOMPARE(b.gains, a.gains);
        QCOMPARE(b.ramps, a.ramps);
        QCOMPARE(b.effortLimit, a.effortLimit);
        QCOMPARE(b.trace.effortIsPower, a.trace.effortIsPower);
        QCOMPARE(b.trace.size(), a.trace.size());
        QCOMPARE(b.trace.edges.size(), a.trace.edges.size());
        const double origin = a.trace.edges.first().time;
        for (int i = 0; i < a.trace.edges.size(); ++i) {
            QVERIFY(std::abs(b.trace.edges[i].time - (a.trace.edges[i].time - origin)) < 1e-9);
            QCOMPARE(b.trace.edges[i].from, a.trace.edges[i].from);
            QCOMPARE(b.trace.edges[i].to, a.trace.edges[i].to);
        }
        for (int i = 0; i < a.trace.size(); ++i) {
            QVERIFY(std::abs(b.trace.time[i] - (a.trace.time[i] - origin)) < 1e-6);
            QVERIFY(std::abs(b.trace.value[i] - a.trace.value[i]) < 1e-6);
            QCOMPARE(StepTrace::isMissing(b.trace.effort[i]),
                     StepTrace::isMissing(a.trace.effort[i]));
            if (!StepTrace::isMissing(a.trace.effort[i]))
                QVERIFY(std::abs(b.trace.effort[i] - a.trace.effort[i]) < 1e-6);
        }
        const QVector<EdgeMetrics> ma = a.metrics();
        const QVector<EdgeMetrics> mb = b.metrics();
        QCOMPARE(mb.size(), ma.size());
        for (int i = 0; i < ma.size(); ++i) {
            QCOMPARE(mb[i].samples, ma[i].samples);
            compareMetric(mb[i].riseTimeS, ma[i].riseTimeS, "rise");
            compareMetric(mb[i].overshootPct, ma[i].overshootPct, "overshoot");
            compareMetric(mb[i].settling2S, ma[i].settling2S, "settling 2 %");
            compareMetric(mb[i].steadyStateError, ma[i].steadyStateError, "error");
            compareMetric(mb[i].peakEffort, ma[i].peakEffort, "peak");
            compareMetric(mb[i].saturatedS, ma[i].saturatedS, "saturation");
            compareMetric(mb[i].oscillations, ma[i].oscillations, "oscillations");
        }
    }
    // An edge at the very time of a sample (the reply that acknowledged the step) keeps that
    // sample in its window after the times are rounded for the files.
    StepRun onSample = positionRun();
    onSample.trace.edges[2].time = onSample.trace.time[121];
    const QString coincident = m_dir.filePath("coincident.lkruns.json");
    QCOMPARE(StepRunFile::save(coincident, {onSample}), QString());
    const auto reloaded = StepRunFile::load(coincident);
    QVERIFY(reloaded);
    QCOMPARE(reloaded->at(0).trace.edges[2].time, reloaded->at(0).trace.time[121]);
    QCOMPARE(reloaded->at(0).metrics().at(2).samples, onSample.metrics().at(2).samples);

    // Saved again, the loaded set gives the same files.
    const QString again = m_dir.filePath("again.lkruns.json");
    QCOMPARE(StepRunFile::save(again, *loaded), QString());
    QCOMPARE(readAll(m_dir.filePath("again.run2.csv")), readAll(m_dir.filePath("trip.run2.csv")));
}

using JsonEdit = std::function<void(QJsonObject &root, QJsonObject &run)>;
Q_DECLARE_METATYPE(JsonEdit)

void tst_StepRunFile::refused_data()
{
    QTest::addColumn<JsonEdit>("edit");
    QTest::addColumn<QByteArray>("rawJson"); // replaces the JSON text when not empty
    QTest::addColumn<QByteArray>("csv");     // replaces run 1's CSV when not empty
    QTest::addColumn<Kind>("kind");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("line");

    const JsonEdit none = [](QJsonObject &, QJsonObject &) {};
    const QString json = "r.lkruns.json";
    const QString csv = "r.run1.csv";
    const auto row = [&](const char *name, JsonEdit edit, Kind kind, const QString &key) {
        QTest::newRow(name) << edit << QByteArray() << QByteArray() << kind << json << key << 0;
    };
    row(
        "wrong format",
        [](QJsonObject &root, QJsonObject &) { root["format"] = "lkstudio-parameters"; },
        Kind::WrongFormat, "format");
    row(
        "no format", [](QJsonObject &root, QJsonObject &) { root.remove("format"); },
        Kind::MissingKey, "format");
    row(
        "newer version", [](QJsonObject &root, QJsonObject &) { root["version"] = 2; },
        Kind::NewerVersion, "version");
    row(
        "version 0", [](QJsonObject &root, QJsonObject &) { root["version"] = 0; },
        Kind::OutOfRange, "version");
    row(
        "version text", [](QJsonObject &root, QJsonObject &) { root["version"] = "1"; },
        Kind::WrongType, "version");
    row(
        "unknown top key", [](QJsonObject &root, QJsonObject &) { root["notes"] = "x"; },
        Kind::UnknownKey, "notes");
    row(
        "runs not array", [](QJsonObject &root, QJsonObject &) { root["runs"] = QJsonObject(); },
        Kind::WrongType, "runs");
    row(
        "missing gains", [](QJsonObject &, QJsonObject &run) { run.remove("gains"); },
        Kind::MissingKey, "runs[1].gains");
    row(
        "unknown run key", [](QJsonObject &, QJsonObject &run) { run["colour"] = "red"; },
        Kind::UnknownKey, "runs[1].colour");
    row(
        "unknown gain",
        [](QJsonObject &, QJsonObject &run) {
            QJsonObject g = run["gains"].toObject();
            g["speed_kx"] = 1;
            run["gains"] = g;
        },
        Kind::UnknownKey, "runs[1].gains.speed_kx");
    row(
        "gain text",
        [](QJsonObject &, QJsonObject &run) {
            QJsonObject g = run["gains"].toObject();
            g["speed_kp"] = "50";
            run["gains"] = g;
        },
        Kind::WrongType, "runs[1].gains.speed_kp");
    row(
        "gain too big",
        [](QJsonObject &, QJsonObject &run) {
            QJsonObject g = run["gains"].toObject();
            g["iq_ki"] = 70000;
            run["gains"] = g;
        },
        Kind::OutOfRange, "runs[1].gains.iq_ki");
    row(
        "fractional ramp",
        [](QJsonObject &, QJsonObject &run) {
            run["ramps"] = QJsonObject{{"speed_ramp_dps2", 1.5}};
        },
        Kind::WrongType, "runs[1].ramps.speed_ramp_dps2");
    row(
        "drive id text", [](QJsonObject &, QJsonObject &run) { run["drive_id"] = "3"; },
        Kind::WrongType, "runs[1].drive_id");
    row(
        "drive id 40", [](QJsonObject &, QJsonObject &run) { run["drive_id"] = 40; },
        Kind::OutOfRange, "runs[1].drive_id");
    row(
        "bad loop",
        [](QJsonObject &, QJsonObject &run) {
            QJsonObject t = run["test"].toObject();
            t["loop"] = "torque";
            run["test"] = t;
        },
        Kind::BadText, "runs[1].test.loop");
    row(
        "zero periods",
        [](QJsonObject &, QJsonObject &run) {
            QJsonObject t = run["test"].toObject();
            t["periods"] = 0;
            run["test"] = t;
        },
        Kind::OutOfRange, "runs[1].test.periods");
    row(
        "bad date", [](QJsonObject &, QJsonObject &run) { run["ran_at"] = "last Tuesday"; },
        Kind::BadText, "runs[1].ran_at");
    row(
        "bad series", [](QJsonObject &, QJsonObject &run) { run["series"] = "MX"; }, Kind::BadText,
        "runs[1].series");
    row(
        "bad generation", [](QJsonObject &, QJsonObject &run) { run["generation"] = "v3"; },
        Kind::BadText, "runs[1].generation");
    row(
        "bad effort", [](QJsonObject &, QJsonObject &run) { run["effort"] = "torque"; },
        Kind::BadText, "runs[1].effort");
    row(
        "negative limit", [](QJsonObject &, QJsonObject &run) { run["effort_limit"] = -5; },
        Kind::OutOfRange, "runs[1].effort_limit");
    row(
        "trace in another folder",
        [](QJsonObject &, QJsonObject &run) { run["trace"] = "../r.run1.csv"; }, Kind::BadText,
        "runs[1].trace");
    row(
        "edge without to",
        [](QJsonObject &, QJsonObject &run) {
            QJsonArray edges = run["edges"].toArray();
            QJsonObject e = edges[1].toObject();
            e.remove("to");
            edges[1] = e;
            run["edges"] = edges;
        },
        Kind::MissingKey, "runs[1].edges[1].to");
    row(
        "edges out of order",
        [](QJsonObject &, QJsonObject &run) {
            QJsonArray edges = run["edges"].toArray();
            QJsonObject e = edges[2].toObject();
            e["time_s"] = 0.1;
            edges[2] = e;
            run["edges"] = edges;
        },
        Kind::EdgesNotAscending, "runs[1].edges[2].time_s");
    row(
        "run not object",
        [](QJsonObject &root, QJsonObject &) {
            QJsonArray runs = root["runs"].toArray();
            runs.append(3);
            root["runs"] = runs;
        },
        Kind::WrongType, "runs[2]");

    const auto raw = [&](const char *name, const QByteArray &text, Kind kind, const QString &key) {
        QTest::newRow(name) << none << text << QByteArray() << kind << json << key << 0;
    };
    raw("not JSON", "{\"format\": ", Kind::NotJson, "");
    raw("not an object", "[1, 2]", Kind::NotObject, "");
    raw("duplicate key", R"({"format":"lkstudio-step-runs","version":1,"runs":[],"version":2})",
        Kind::DuplicateKey, "version");

    const auto bad = [&](const char *name, const QByteArray &text, Kind kind, int line) {
        QTest::newRow(name) << none << QByteArray() << text << kind << csv << QString() << line;
    };
    bad("csv header", "time,value,effort\n0,1,2\n", Kind::CsvBadHeader, 1);
    bad("csv value", "time_s,value,effort\n0.0,1,\n0.1,1.5x,2\n", Kind::CsvBadNumber, 3);
    bad("csv empty value", "time_s,value,effort\n0.0,,1\n", Kind::CsvBadNumber, 2);
    bad("csv effort", "time_s,value,effort\n0.0,1,abc\n", Kind::CsvBadNumber, 2);
    bad("csv nan", "time_s,value,effort\n0.0,nan,1\n", Kind::CsvBadNumber, 2);
    bad("csv time back", "time_s,value,effort\n0.0,1,\n0.2,1,\n0.1,1,\n", Kind::CsvTimeNotAscending,
        4);
    bad("csv two cells", "time_s,value,effort\n0.0,1\n", Kind::CsvBadRow, 2);
    bad("csv blank line", "time_s,value,effort\n0.0,1,\n\n0.1,1,\n", Kind::CsvBadRow, 3);
}

void tst_StepRunFile::refused()
{
    QFETCH(JsonEdit, edit);
    QFETCH(QByteArray, rawJson);
    QFETCH(QByteArray, csv);
    QFETCH(Kind, kind);
    QFETCH(QString, file);
    QFETCH(QString, key);
    QFETCH(int, line);

    QTemporaryDir dir;
    const QString json = dir.filePath("r.lkruns.json");
    QCOMPARE(StepRunFile::save(json, {speedRun(), positionRun()}), QString());
    QVERIFY(StepRunFile::load(json)); // the file is good before the edit
    if (!rawJson.isEmpty()) {
        writeAll(json, rawJson);
    } else if (!csv.isEmpty()) {
        writeAll(dir.filePath("r.run1.csv"), csv);
    } else {
        QJsonObject root = QJsonDocument::fromJson(readAll(json)).object();
        QJsonArray runs = root["runs"].toArray();
        QJsonObject run = runs[1].toObject();
        edit(root, run);
        if (root["runs"].isArray() && root["runs"].toArray().size() == 2) {
            runs[1] = run;
            root["runs"] = runs;
        }
        writeAll(json, QJsonDocument(root).toJson());
    }
    StepRunFileError error;
    QVERIFY(!StepRunFile::load(json, &error));
    QCOMPARE(error.kind, kind);
    QCOMPARE(error.path, dir.filePath(file));
    QCOMPARE(error.key, key);
    QCOMPARE(error.line, line);
    QVERIFY(error.toString().contains(file));
    if (line > 0)
        QVERIFY2(error.toString().contains(QStringLiteral("line %1").arg(line)),
                 qPrintable(error.toString()));
    if (!key.isEmpty())
        QVERIFY2(error.toString().contains(key), qPrintable(error.toString()));
}

// Two samples whose times round to the same microsecond in the file still load.
void tst_StepRunFile::equalTimesLoad()
{
    QTemporaryDir dir;
    const QString json = dir.filePath("e.lkruns.json");
    StepRun run = speedRun();
    run.trace.time[50] = run.trace.time[49] + 1e-7;
    QCOMPARE(StepRunFile::save(json, {run}), QString());
    const auto loaded = StepRunFile::load(json);
    QVERIFY(loaded);
    QCOMPARE(loaded->at(0).trace.time[50], loaded->at(0).trace.time[49]);
}

void tst_StepRunFile::missingJson()
{
    StepRunFileError error;
    QVERIFY(!StepRunFile::load(m_dir.filePath("nowhere.lkruns.json"), &error));
    QCOMPARE(error.kind, Kind::CannotRead);
    QCOMPARE(error.path, m_dir.filePath("nowhere.lkruns.json"));
    QVERIFY(!error.detail.isEmpty());
}

void tst_StepRunFile::missingTrace()
{
    QTemporaryDir dir;
    const QString json = dir.filePath("m.lkruns.json");
    QCOMPARE(StepRunFile::save(json, {speedRun(), positionRun()}), QString());
    QVERIFY(QFile::remove(dir.filePath("m.run2.csv")));
    StepRunFileError error;
    QVERIFY(!StepRunFile::load(json, &error));
    QCOMPARE(error.kind, Kind::MissingTrace);
    QCOMPARE(error.path, dir.filePath("m.run2.csv"));
    QCOMPARE(error.key, QString("runs[1].trace"));
}

// A folder that does not exist: the error names the file, and no JSON appears.
void tst_StepRunFile::saveFailureNamesTheFile()
{
    const QString json = m_dir.filePath("no/such/folder/x.lkruns.json");
    const QString error = StepRunFile::save(json, {speedRun()});
    QVERIFY(!error.isEmpty());
    QVERIFY2(error.contains("x.run1.csv"), qPrintable(error));
    QVERIFY(!QFile::exists(json));
}

void tst_StepRunFile::traceFileNames()
{
    QCOMPARE(StepRunFile::traceFileName("/a/b/bench.lkruns.json", 0), QString("bench.run1.csv"));
    QCOMPARE(StepRunFile::traceFileName("bench.json", 2), QString("bench.run3.csv"));
    QCOMPARE(StepRunFile::traceFileName("/a/bench", 9), QString("bench.run10.csv"));
}

QTEST_GUILESS_MAIN(tst_StepRunFile)
#include "tst_steprunfile.moc"
