#include "StepRunFile.h"

#include "StepRunJson.h"
#include "StepTraceCsv.h"

#include <protocol/Series.h>
#include <record/CsvWriter.h>
#include <record/ParameterSet.h>
#include <safety/JsonKeyCheck.h>
#include <system/BoundedFile.h>

#include <QtCore/QBuffer>
#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>

#include <cmath>
#include <iterator>
#include <limits>

namespace lk::tuning {

namespace {

using Kind = StepRunFileError::Kind;
using ValueType = StepRunFileError::ValueType;

constexpr double kAnyNumber = 1e12; // physical values and times: finite, and not absurd
constexpr double kGainMax = 65535;  // V2.35's 16-bit gains; V2.3's are 0..255
constexpr double kRampMax = 2147483647;

struct Field {
    const char *key;
    ValueType type;
    double min = 0;
    double max = 0;
    bool nullable = false;
};

QString jsonText(const QJsonValue &v)
{
    const QByteArray array = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(array.mid(1, array.size() - 2)); // without the brackets
}

QString effortWord(bool isPower)
{
    return isPower ? QStringLiteral("power") : QStringLiteral("iq_a");
}

/// Reads the JSON of a run file, remembering the first fault. Every check returns false once
/// something was refused, so a caller can chain them.
class Reader {
public:
    explicit Reader(StepRunFileError *error) : m_error(error) {}

    bool refuse(Kind kind, const QString &key, const QJsonValue &found = QJsonValue::Undefined,
                const Field *field = nullptr)
    {
        if (m_error) {
            m_error->kind = kind;
            m_error->key = key;
            if (!found.isUndefined())
                m_error->found = jsonText(found);
            if (field) {
                m_error->expected = field->type;
                m_error->min = field->min;
                m_error->max = field->max;
            }
        }
        return false;
    }

    bool value(const QJsonValue &v, const Field &f, const QString &key)
    {
        if (v.isNull() && f.nullable)
            return true;
        bool typeOk = false;
        switch (f.type) {
        case ValueType::Object:
            typeOk = v.isObject();
            break;
        case ValueType::Array:
            typeOk = v.isArray();
            break;
        case ValueType::Text:
            typeOk = v.isString();
            break;
        case ValueType::Integer:
        case ValueType::Number: {
            const double d = v.toDouble(std::numeric_limits<double>::quiet_NaN());
            typeOk = v.isDouble() && std::isfinite(d) &&
                     (f.type == ValueType::Number || d == std::floor(d));
            if (typeOk && (d < f.min || d > f.max))
                return refuse(Kind::OutOfRange, key, v, &f);
            break;
        }
        }
        return typeOk || refuse(Kind::WrongType, key, v, &f);
    }

    /// Every key known, every field there, every value of its type and in its range.
    bool object(const QJsonObject &o, const QString &prefix, std::initializer_list<Field> fields)
    {
        for (auto it = o.begin(); it != o.end(); ++it) {
            const bool known = std::any_of(fields.begin(), fields.end(), [&](const Field &f) {
                return it.key() == QLatin1String(f.key);
            });
            if (!known)
                return refuse(Kind::UnknownKey, prefix + it.key());
        }
        for (const Field &f : fields) {
            const QString key = prefix + QLatin1String(f.key);
            const QJsonValue v = o.value(QLatin1String(f.key));
            if (v.isUndefined())
                return refuse(Kind::MissingKey, key, QJsonValue::Undefined, &f);
            if (!value(v, f, key))
                return false;
        }
        return true;
    }

    /// An object whose keys are any of `keys`, each an integer in 0..max.
    bool integerMap(const QJsonObject &o, const QString &prefix, const QStringList &keys,
                    double max)
    {
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (!keys.contains(it.key()))
                return refuse(Kind::UnknownKey, prefix + it.key());
            if (!value(it.value(), Field{"", ValueType::Integer, 0, max}, prefix + it.key()))
                return false;
        }
        return true;
    }

private:
    StepRunFileError *m_error;
};

bool readTest(Reader &r, const QJsonObject &o, const QString &prefix, StepRunSpec &spec)
{
    if (!r.object(o, prefix,
                  {{"loop", ValueType::Text},
                   {"from", ValueType::Number, -kAnyNumber, kAnyNumber},
                   {"to", ValueType::Number, -kAnyNumber, kAnyNumber},
                   {"duration_s", ValueType::Number, 0, 1e6},
                   {"periods", ValueType::Integer, 1, 1e6}}))
        return false;
    const std::optional<StepLoop> loop = stepLoopFromWord(o.value("loop").toString());
    if (!loop)
        return r.refuse(Kind::BadText, prefix + "loop", o.value("loop"));
    spec.loop = *loop;
    spec.from = o.value("from").toDouble();
    spec.to = o.value("to").toDouble();
    spec.durationS = o.value("duration_s").toDouble();
    spec.periods = o.value("periods").toInt();
    return true;
}

bool readEdges(Reader &r, const QJsonArray &edges, const QString &prefix, StepTrace &trace)
{
    for (int i = 0; i < edges.size(); ++i) {
        const QString at = prefix + QStringLiteral("[%1]").arg(i);
        if (!r.value(edges[i], Field{"", ValueType::Object}, at))
            return false;
        const QJsonObject o = edges[i].toObject();
        if (!r.object(o, at + '.',
                      {{"time_s", ValueType::Number, -kAnyNumber, kAnyNumber},
                       {"from", ValueType::Number, -kAnyNumber, kAnyNumber},
                       {"to", ValueType::Number, -kAnyNumber, kAnyNumber}}))
            return false;
        const StepEdge edge{o.value("time_s").toDouble(), o.value("from").toDouble(),
                            o.value("to").toDouble()};
        if (!trace.edges.isEmpty() && edge.time < trace.edges.last().time)
            return r.refuse(Kind::EdgesNotAscending, at + ".time_s", o.value("time_s"));
        trace.edges.append(edge);
    }
    return true;
}

/// The run's identity and texts that must be one of a few words.
bool readIdentity(Reader &r, const QJsonObject &o, const QString &prefix, StepRun &run)
{
    run.number = o.value("number").toInt();
    run.label = o.value("label").toString();
    run.driveId = o.value("drive_id").toInt();
    run.series = o.value("series").toString();
    run.model = o.value("model").toString();
    run.generation = o.value("generation").toString();
    if (!run.series.isEmpty() && !protocol::seriesFromName(run.series))
        return r.refuse(Kind::BadText, prefix + "series", o.value("series"));
    if (!run.generation.isEmpty() && !protocol::generationFromName(run.generation))
        return r.refuse(Kind::BadText, prefix + "generation", o.value("generation"));
    if (!o.value("ran_at").isNull()) {
        run.ranAt = QDateTime::fromString(o.value("ran_at").toString(), Qt::ISODateWithMs);
        if (!run.ranAt.isValid())
            return r.refuse(Kind::BadText, prefix + "ran_at", o.value("ran_at"));
        run.ranAt = run.ranAt.toUTC();
    }
    const QString effort = o.value("effort").toString();
    if (effort != effortWord(false) && effort != effortWord(true))
        return r.refuse(Kind::BadText, prefix + "effort", o.value("effort"));
    run.trace.effortIsPower = effort == effortWord(true);
    if (!o.value("effort_limit").isNull())
        run.effortLimit = o.value("effort_limit").toDouble();
    return true;
}

/// One run of the JSON file, without its samples; `traceName` is the CSV it names.
bool readRun(Reader &r, const QJsonValue &value, int index, StepRun &run, QString &traceName)
{
    const QString prefix = QStringLiteral("runs[%1].").arg(index);
    if (!r.value(value, Field{"", ValueType::Object}, prefix.chopped(1)))
        return false;
    const QJsonObject o = value.toObject();
    if (!r.object(o, prefix,
                  {{"number", ValueType::Integer, 0, std::numeric_limits<int>::max()},
                   {"label", ValueType::Text},
                   {"ran_at", ValueType::Text, 0, 0, true},
                   {"drive_id", ValueType::Integer, 1, 32},
                   {"series", ValueType::Text},
                   {"model", ValueType::Text},
                   {"generation", ValueType::Text},
                   {"test", ValueType::Object},
                   {"gains", ValueType::Object},
                   {"ramps", ValueType::Object},
                   {"effort", ValueType::Text},
                   {"effort_limit", ValueType::Number, 1e-6, kAnyNumber, true},
                   {"edges", ValueType::Array},
                   {"trace", ValueType::Text},
                   {"metrics", ValueType::Object}}))
        return false;
    if (!readIdentity(r, o, prefix, run) ||
        !readTest(r, o.value("test").toObject(), prefix + "test.", run.spec) ||
        !r.integerMap(o.value("gains").toObject(), prefix + "gains.", stepRunGainKeys(),
                      kGainMax) ||
        !r.integerMap(o.value("ramps").toObject(), prefix + "ramps.", stepRunRampKeys(),
                      kRampMax) ||
        !readEdges(r, o.value("edges").toArray(), prefix + "edges", run.trace))
        return false;
    run.gains = o.value("gains").toObject();
    run.ramps = o.value("ramps").toObject();
    traceName = o.value("trace").toString();
    // A bare file name beside the JSON: a file may not send the reader to another folder.
    const bool bare = !traceName.isEmpty() && !traceName.contains('/') &&
                      !traceName.contains('\\') && traceName != "." && traceName != "..";
    return bare || r.refuse(Kind::BadText, prefix + "trace", o.value("trace"));
}

/// The format header and the runs, without their samples; `traceNames` gets each run's CSV.
bool readDocument(Reader &r, const QJsonObject &root, QVector<StepRun> &runs,
                  QStringList &traceNames)
{
    const QJsonValue format = root.value("format");
    if (format.isUndefined())
        return r.refuse(Kind::MissingKey, "format");
    if (format.toString() != QLatin1String(StepRunFile::kFormatName))
        return r.refuse(Kind::WrongFormat, "format", format);
    const QJsonValue version = root.value("version");
    if (version.isDouble() && version.toDouble() > StepRunFile::kFormatVersion)
        return r.refuse(Kind::NewerVersion, "version", version);
    if (!r.object(root, QString(),
                  {{"format", ValueType::Text},
                   {"version", ValueType::Integer, 1, StepRunFile::kFormatVersion},
                   {"runs", ValueType::Array}}))
        return false;
    const QJsonArray array = root.value("runs").toArray();
    for (int i = 0; i < array.size(); ++i) {
        StepRun run;
        QString traceName;
        if (!readRun(r, array[i], i, run, traceName))
            return false;
        runs.append(run);
        traceNames.append(traceName);
    }
    return true;
}

/// `file`'s failure as the error of a run file: too large, or unreadable as `unreadable`.
void fileError(const system::FileReadError &file, qint64 maxBytes, Kind unreadable,
               StepRunFileError &e)
{
    e.kind = file.kind == system::FileReadError::Kind::TooLarge ? Kind::TooLarge : unreadable;
    e.detail = file.reason(); // a directory, a FIFO, a device: refused unopened
    if (e.kind == Kind::TooLarge) {
        e.max = double(maxBytes);
        e.found = QString::number(file.size);
    }
}

bool readJsonFile(const QString &path, QJsonObject &root, StepRunFileError *error)
{
    StepRunFileError e;
    const system::BoundedRead file = system::BoundedFile::read(path, StepRunFile::kMaxJsonBytes);
    if (!file.ok()) {
        fileError(*file.error, StepRunFile::kMaxJsonBytes, Kind::CannotRead, e);
    } else {
        const QByteArray &bytes = file.bytes;
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
        if (parseError.error != QJsonParseError::NoError) {
            e.kind = Kind::NotJson;
            e.detail = parseError.errorString();
            e.offset = parseError.offset;
        } else if (!doc.isObject()) {
            e.kind = Kind::NotObject;
        } else if (const std::optional<QString> twice = safety::JsonKeyCheck::duplicateKey(bytes)) {
            e.kind = Kind::DuplicateKey;
            e.key = *twice;
        } else {
            root = doc.object();
            return true;
        }
    }
    e.path = path;
    if (error)
        *error = e;
    return false;
}

/// The samples of `run` from the CSV `name` beside `jsonPath`; `budget` is what the set's
/// traces may still take (kMaxSetTraceBytes in all), less this one's size on success.
bool readTrace(const QString &jsonPath, const QString &name, int index, StepRun &run,
               qint64 &budget, StepRunFileError *error)
{
    StepRunFileError e;
    e.path = QFileInfo(jsonPath).dir().filePath(name);
    const qint64 bound = std::min(StepRunFile::kMaxTraceBytes, budget);
    const system::BoundedRead file = system::BoundedFile::read(e.path, bound);
    bool ok = false;
    if (!file.ok()) {
        fileError(*file.error, bound, Kind::MissingTrace, e);
        if (e.kind == Kind::MissingTrace) {
            e.key = QStringLiteral("runs[%1].trace").arg(index);
            e.found = jsonText(name);
        }
    } else {
        QBuffer buffer;
        buffer.setData(file.bytes);
        buffer.open(QIODevice::ReadOnly);
        ok = StepTraceCsv::read(buffer, run.trace, &e);
        budget -= file.bytes.size();
    }
    if (!ok && error)
        *error = e;
    return ok;
}

} // namespace

QString StepRunFileError::toString() const
{
    QString where = path;
    if (!key.isEmpty())
        where += QStringLiteral(": ") + key;
    if (line > 0)
        where += QStringLiteral(": line %1").arg(line);
    if (!column.isEmpty())
        where += QStringLiteral(" (%1)").arg(column);
    static const char *const names[] = {"cannot read",
                                        "too large",
                                        "not JSON",
                                        "not a JSON object",
                                        "wrong format",
                                        "newer version",
                                        "missing key",
                                        "unknown key",
                                        "key given twice",
                                        "wrong type",
                                        "out of range",
                                        "meaningless text",
                                        "edges not in time order",
                                        "trace file missing",
                                        "bad CSV header",
                                        "bad CSV row",
                                        "bad number",
                                        "time goes back"};
    static_assert(std::size(names) == size_t(Kind::CsvTimeNotAscending) + 1);
    QString text = where + QStringLiteral(": ") + QLatin1String(names[int(kind)]);
    if (!found.isEmpty())
        text += QStringLiteral(" (found %1)").arg(found);
    if (!detail.isEmpty())
        text += QStringLiteral(": ") + detail;
    return text;
}

QString StepRunFile::traceFileName(const QString &jsonPath, int index)
{
    QString name = QFileInfo(jsonPath).fileName();
    if (name.endsWith(QLatin1String(kSuffix)))
        name.chop(int(qstrlen(kSuffix)));
    else if (name.endsWith(QLatin1String(".json")))
        name.chop(5);
    return name + QStringLiteral(".run%1.csv").arg(index + 1);
}

double StepRunFile::timeOrigin(const StepTrace &trace)
{
    if (!trace.edges.isEmpty())
        return trace.edges.first().time;
    return trace.time.isEmpty() ? 0.0 : trace.time.first();
}

QJsonObject StepRunFile::toJson(const QVector<StepRun> &runs, const QStringList &traceNames)
{
    QJsonArray array;
    for (int i = 0; i < runs.size(); ++i) {
        const StepRun &run = runs[i];
        const double origin = timeOrigin(run.trace);
        QJsonArray edges;
        for (const StepEdge &e : run.trace.edges)
            edges.append(QJsonObject{{"time_s", StepTraceCsv::fileTime(e.time, origin)},
                                     {"from", e.from},
                                     {"to", e.to}});
        const StepRunSpec &s = run.spec;
        array.append(QJsonObject{
            {"number", run.number},
            {"label", run.label},
            {"ran_at", run.ranAt.isValid()
                           ? QJsonValue(run.ranAt.toUTC().toString(Qt::ISODateWithMs))
                           : QJsonValue(QJsonValue::Null)},
            {"drive_id", run.driveId},
            {"series", run.series},
            {"model", run.model},
            {"generation", run.generation},
            {"test", QJsonObject{{"loop", stepLoopWord(s.loop)},
                                 {"from", s.from},
                                 {"to", s.to},
                                 {"duration_s", s.durationS},
                                 {"periods", s.periods}}},
            {"gains", run.gains},
            {"ramps", run.ramps},
            {"effort", effortWord(run.trace.effortIsPower)},
            {"effort_limit",
             run.effortLimit ? QJsonValue(*run.effortLimit) : QJsonValue(QJsonValue::Null)},
            {"edges", edges},
            {"trace", traceNames.value(i)},
            {"metrics", StepRunJson::metricsObject(run.stepMetrics(), run.trace.effortIsPower)},
        });
    }
    return QJsonObject{
        {"format", QLatin1String(kFormatName)}, {"version", kFormatVersion}, {"runs", array}};
}

QByteArray StepRunFile::traceCsv(const StepRun &run)
{
    return StepTraceCsv::header() + StepTraceCsv::rows(run.trace, timeOrigin(run.trace));
}

QString StepRunFile::save(const QString &jsonPath, const QVector<StepRun> &runs)
{
    // Never write a set load() would refuse: the traces are checked against its bounds first.
    QVector<QByteArray> traces;
    qint64 total = 0;
    for (const StepRun &run : runs) {
        traces.append(traceCsv(run));
        total += traces.last().size();
        if (traces.last().size() > kMaxTraceBytes || total > kMaxSetTraceBytes)
            return QCoreApplication::translate("lk::tuning::StepRunFile",
                                               "Run %1 was not saved: its trace is %2, and a "
                                               "trace file may hold %3 (a set's traces %4 in "
                                               "all). Keep a shorter run.")
                .arg(run.number)
                .arg(system::BoundedFile::sizeText(traces.last().size()),
                     system::BoundedFile::sizeText(kMaxTraceBytes),
                     system::BoundedFile::sizeText(kMaxSetTraceBytes));
    }
    const QDir dir = QFileInfo(jsonPath).dir();
    QStringList names;
    for (int i = 0; i < runs.size(); ++i) {
        names.append(traceFileName(jsonPath, i));
        record::CsvWriter csv(dir.filePath(names.last()));
        QString error = csv.begin(QByteArray());
        if (error.isEmpty()) {
            csv.write(traces.at(i));
            error = csv.finish();
        }
        if (!error.isEmpty())
            return error;
    }
    return record::writeFileAtomically(jsonPath, QJsonDocument(toJson(runs, names)).toJson());
}

std::optional<QVector<StepRun>> StepRunFile::load(const QString &jsonPath, StepRunFileError *error)
{
    QJsonObject root;
    if (!readJsonFile(jsonPath, root, error))
        return std::nullopt;
    QVector<StepRun> runs;
    QStringList traceNames;
    StepRunFileError e;
    Reader reader(&e);
    if (!readDocument(reader, root, runs, traceNames)) {
        e.path = jsonPath;
        if (error)
            *error = e;
        return std::nullopt;
    }
    qint64 budget = kMaxSetTraceBytes;
    for (int i = 0; i < runs.size(); ++i)
        if (!readTrace(jsonPath, traceNames[i], i, runs[i], budget, error))
            return std::nullopt;
    return runs;
}

} // namespace lk::tuning
