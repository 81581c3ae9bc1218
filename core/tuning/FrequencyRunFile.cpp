#include "FrequencyRunFile.h"

#include <protocol/Series.h>
#include <record/ParameterFileCheck.h>
#include <system/AtomicFile.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>

#include <vector>

namespace lk::tuning {

namespace {

using record::FileField;
using record::ParameterFileCheck;
using record::ParameterFileError;
using Kind = ParameterFileError::Kind;
using Type = ParameterFileError::ValueType;

constexpr double kAny = 1e12;      // physical values: finite, not absurd
constexpr double kGainMax = 65535; // V2.35's 16-bit gains; V2.3's are 0..255

const std::vector<FileField> &rootFields()
{
    static const std::vector<FileField> f{
        {"format", Type::Text},
        {"version", Type::Integer, 1, 1000000},
        {"number", Type::Integer, 0, 1000000},
        {"label", Type::Text},
        {"ran_at", Type::Text},
        {"drive_id", Type::Integer, 1, 32},
        {"series", Type::Text},
        {"model", Type::Text},
        {"loop", Type::Text},
        {"from_hz", Type::Number, FrequencySweepSpec::kMinHz, FrequencySweepSpec::kMaxHz},
        {"to_hz", Type::Number, FrequencySweepSpec::kMinHz, FrequencySweepSpec::kMaxHz},
        {"points_planned", Type::Integer, 1, FrequencySweepSpec::kMaxPoints},
        {"amplitude", Type::Number, 0, kAny},
        {"operating_point", Type::Number, -kAny, kAny},
        {"gains", Type::Object, 0, 0, false},
        {"sample_rate_hz", Type::Number, 0, kAny},
    };
    return f;
}

const std::vector<FileField> &pointFields()
{
    static const std::vector<FileField> f{
        {"hz", Type::Number, FrequencySweepSpec::kMinHz, FrequencySweepSpec::kMaxHz},
        {"magnitude_db", Type::Number, -1000, 1000},
        {"phase_deg", Type::Number, -1e6, 1e6},
        {"quality", Type::Number, 0, 1},
        {"samples", Type::Integer, 0, 1e9},
        {"input_amplitude", Type::Number, 0, kAny},
        {"output_amplitude", Type::Number, 0, kAny},
    };
    return f;
}

const std::vector<FileField> &droppedFields()
{
    static const std::vector<FileField> f{
        {"hz", Type::Number, FrequencySweepSpec::kMinHz, FrequencySweepSpec::kMaxHz},
        {"reason", Type::Text},
    };
    return f;
}

const std::vector<FileField> &gainFields()
{
    static const std::vector<FileField> f{
        {"generation", Type::Text},
        {"angle_kp", Type::Integer, 0, kGainMax},
        {"angle_ki", Type::Integer, 0, kGainMax},
        {"angle_kd", Type::Integer, 0, kGainMax},
        {"speed_kp", Type::Integer, 0, kGainMax},
        {"speed_ki", Type::Integer, 0, kGainMax},
        {"speed_kd", Type::Integer, 0, kGainMax},
        {"current_kp", Type::Integer, 0, kGainMax},
        {"current_ki", Type::Integer, 0, kGainMax},
        {"current_kd", Type::Integer, 0, kGainMax},
        {"acceleration_dps2", Type::Integer, 0, 2147483647},
    };
    return f;
}

// The arrays, beside the keys of rootFields().
const char *const kArrays[] = {"points", "dropped"};

/// A text that is none of `words` (e.g. "\"speed\" or \"position\""): WrongType of Text with
/// the words allowed in `detail`.
bool badText(ParameterFileError *error, const QString &key, const QJsonValue &found,
             const QString &words)
{
    ParameterFileError e = ParameterFileCheck::textError(Kind::WrongType, key, found);
    e.detail = words;
    return ParameterFileCheck::refuse(error, e);
}

/// Each element of the array at `key` an object of `fields`; `read` takes each in turn.
template <typename Read>
bool readArray(const QJsonObject &root, const char *key, const std::vector<FileField> &fields,
               ParameterFileError *error, Read read)
{
    const QString name = QLatin1String(key);
    const QJsonValue v = root.value(name);
    if (v.isUndefined())
        return ParameterFileCheck::refuse(
            error,
            ParameterFileCheck::keyError(Kind::MissingKey, name, FileField{key, Type::Object}, v));
    if (!v.isArray())
        return ParameterFileCheck::refuse(
            error,
            ParameterFileCheck::keyError(Kind::WrongType, name, FileField{key, Type::Object}, v));
    const QJsonArray a = v.toArray();
    if (a.size() > 10 * FrequencySweepSpec::kMaxPoints)
        return ParameterFileCheck::refuse(
            error, ParameterFileCheck::keyError(
                       Kind::OutOfRange, name,
                       FileField{key, Type::Integer, 0, 10.0 * FrequencySweepSpec::kMaxPoints},
                       QJsonValue(a.size())));
    for (int i = 0; i < a.size(); ++i) {
        const QString at = QStringLiteral("%1[%2]").arg(name).arg(i);
        if (!a.at(i).isObject())
            return ParameterFileCheck::refuse(
                error, ParameterFileCheck::keyError(Kind::WrongType, at,
                                                    FileField{key, Type::Object}, a.at(i)));
        const QJsonObject o = a.at(i).toObject();
        if (!ParameterFileCheck::checkObject(o, at + QLatin1Char('.'), fields, error) ||
            !read(o, at))
            return false;
    }
    return true;
}

std::optional<LoopGains> readGains(const QJsonValue &v, ParameterFileError *error, bool *ok)
{
    *ok = true;
    if (v.isNull())
        return std::nullopt;
    const QJsonObject o = v.toObject();
    *ok = ParameterFileCheck::checkObject(o, QStringLiteral("gains."), gainFields(), error);
    if (!*ok)
        return std::nullopt;
    const auto generation = protocol::generationFromName(o.value("generation").toString());
    if (!generation) {
        *ok = ParameterFileCheck::refuse(
            error, ParameterFileCheck::textError(Kind::UnknownGeneration,
                                                 QStringLiteral("gains.generation"),
                                                 o.value("generation")));
        return std::nullopt;
    }
    LoopGains g;
    g.generation = *generation;
    const auto u16 = [&o](const char *k) { return quint16(o.value(QLatin1String(k)).toInt()); };
    g.angle = {u16("angle_kp"), u16("angle_ki"), u16("angle_kd")};
    g.speed = {u16("speed_kp"), u16("speed_ki"), u16("speed_kd")};
    g.current = {u16("current_kp"), u16("current_ki"), u16("current_kd")};
    g.accelerationDps2 = o.value("acceleration_dps2").toInteger();
    return g;
}

QJsonObject gainsJson(const LoopGains &g)
{
    return {{"generation", protocol::generationName(g.generation)},
            {"angle_kp", g.angle.kp},
            {"angle_ki", g.angle.ki},
            {"angle_kd", g.angle.kd},
            {"speed_kp", g.speed.kp},
            {"speed_ki", g.speed.ki},
            {"speed_kd", g.speed.kd},
            {"current_kp", g.current.kp},
            {"current_ki", g.current.ki},
            {"current_kd", g.current.kd},
            {"acceleration_dps2", g.accelerationDps2}};
}

std::optional<DroppedReason> reasonFromWord(const QString &word)
{
    for (DroppedReason r :
         {DroppedReason::AboveResolution, DroppedReason::TooFewSamples, DroppedReason::NoInput})
        if (word == QLatin1String(FrequencyRunFile::droppedWord(r)))
            return r;
    return std::nullopt;
}

} // namespace

QString FrequencyRunFile::loopWord(SweepLoop loop)
{
    return loop == SweepLoop::Position ? QStringLiteral("position") : QStringLiteral("speed");
}

const char *FrequencyRunFile::droppedWord(DroppedReason reason)
{
    switch (reason) {
    case DroppedReason::AboveResolution:
        return "above_resolution";
    case DroppedReason::TooFewSamples:
        return "too_few_samples";
    case DroppedReason::NoInput:
        return "no_input";
    }
    return "";
}

QJsonObject FrequencyRunFile::toJson(const FrequencyRun &run)
{
    QJsonArray points;
    for (const FrequencyPoint &p : run.response.points)
        points.append(QJsonObject{{"hz", p.hz},
                                  {"magnitude_db", p.magnitudeDb},
                                  {"phase_deg", p.phaseDeg},
                                  {"quality", p.quality},
                                  {"samples", p.samples},
                                  {"input_amplitude", p.inputAmplitude},
                                  {"output_amplitude", p.outputAmplitude}});
    QJsonArray dropped;
    for (const DroppedFrequency &d : run.response.dropped)
        dropped.append(QJsonObject{{"hz", d.hz}, {"reason", QLatin1String(droppedWord(d.reason))}});
    return {{"format", QLatin1String(kFormatName)},
            {"version", kFormatVersion},
            {"number", run.number},
            {"label", run.label},
            {"ran_at", run.ranAt.toUTC().toString(Qt::ISODateWithMs)},
            {"drive_id", run.driveId},
            {"series", run.series},
            {"model", run.model},
            {"loop", loopWord(run.spec.loop)},
            {"from_hz", run.spec.fromHz},
            {"to_hz", run.spec.toHz},
            {"points_planned", run.spec.points},
            {"amplitude", run.spec.amplitude},
            {"operating_point", run.spec.centre()},
            {"gains", run.gains ? QJsonValue(gainsJson(*run.gains)) : QJsonValue()},
            {"sample_rate_hz", run.response.sampleRateHz},
            {"points", points},
            {"dropped", dropped}};
}

std::optional<FrequencyRun> FrequencyRunFile::fromJson(const QJsonObject &root,
                                                       ParameterFileError *error)
{
    QJsonObject keys = root; // the arrays are checked element by element below
    for (const char *array : kArrays)
        keys.remove(QLatin1String(array));
    if (!ParameterFileCheck::checkHeader(root, kFormatName, kFormatVersion, error) ||
        !ParameterFileCheck::checkObject(keys, QString(), rootFields(), error))
        return std::nullopt;
    FrequencyRun run;
    run.number = root.value("number").toInt();
    run.label = root.value("label").toString();
    run.ranAt = QDateTime::fromString(root.value("ran_at").toString(), Qt::ISODateWithMs);
    if (!run.ranAt.isValid()) {
        ParameterFileCheck::refuse(error, ParameterFileCheck::textError(Kind::BadTimestamp,
                                                                        QStringLiteral("ran_at"),
                                                                        root.value("ran_at")));
        return std::nullopt;
    }
    run.driveId = root.value("drive_id").toInt();
    run.series = root.value("series").toString();
    if (!run.series.isEmpty() && !protocol::seriesFromName(run.series)) {
        ParameterFileCheck::refuse(error, ParameterFileCheck::textError(Kind::UnknownSeries,
                                                                        QStringLiteral("series"),
                                                                        root.value("series")));
        return std::nullopt;
    }
    run.model = root.value("model").toString();
    const QString loop = root.value("loop").toString();
    if (loop != loopWord(SweepLoop::Speed) && loop != loopWord(SweepLoop::Position)) {
        badText(error, QStringLiteral("loop"), root.value("loop"),
                QStringLiteral("\"speed\" or \"position\""));
        return std::nullopt;
    }
    FrequencySweepSpec &s = run.spec;
    s.id = run.driveId;
    s.loop = loop == loopWord(SweepLoop::Position) ? SweepLoop::Position : SweepLoop::Speed;
    s.fromHz = root.value("from_hz").toDouble();
    s.toHz = root.value("to_hz").toDouble();
    s.points = root.value("points_planned").toInt();
    s.amplitude = root.value("amplitude").toDouble();
    s.operatingPoint = root.value("operating_point").toDouble();
    bool gainsOk = true;
    run.gains = readGains(root.value("gains"), error, &gainsOk);
    if (!gainsOk)
        return std::nullopt;
    run.response.sampleRateHz = root.value("sample_rate_hz").toDouble();
    run.response.samplesPerPeriod = s.samplesPerPeriod();
    const bool pointsOk =
        readArray(root, "points", pointFields(), error, [&](const QJsonObject &o, const QString &) {
            FrequencyPoint p;
            p.hz = o.value("hz").toDouble();
            p.magnitudeDb = o.value("magnitude_db").toDouble();
            p.phaseDeg = o.value("phase_deg").toDouble();
            p.quality = o.value("quality").toDouble();
            p.samples = o.value("samples").toInt();
            p.inputAmplitude = o.value("input_amplitude").toDouble();
            p.outputAmplitude = o.value("output_amplitude").toDouble();
            run.response.points.append(p);
            return true;
        });
    const bool droppedOk =
        pointsOk &&
        readArray(root, "dropped", droppedFields(), error,
                  [&](const QJsonObject &o, const QString &at) {
                      const auto why = reasonFromWord(o.value("reason").toString());
                      if (!why)
                          return badText(error, at + QStringLiteral(".reason"), o.value("reason"),
                                         QStringLiteral("\"above_resolution\", "
                                                        "\"too_few_samples\" or "
                                                        "\"no_input\""));
                      run.response.dropped.append({o.value("hz").toDouble(), *why});
                      return true;
                  });
    if (!droppedOk)
        return std::nullopt;
    return run;
}

QString FrequencyRunFile::save(const QString &path, const FrequencyRun &run)
{
    return system::AtomicFile::writeAll(path, QJsonDocument(toJson(run)).toJson());
}

std::optional<FrequencyRun> FrequencyRunFile::load(const QString &path, ParameterFileError *error)
{
    const auto fail = [&]() -> std::optional<FrequencyRun> {
        if (error)
            error->path = path;
        return std::nullopt;
    };
    const std::optional<QByteArray> bytes =
        ParameterFileCheck::readFile(path, kMaxFileBytes, error);
    QJsonObject root;
    if (!bytes || !ParameterFileCheck::parseObject(*bytes, root, error))
        return fail();
    std::optional<FrequencyRun> run = fromJson(root, error);
    if (!run)
        return fail();
    return run;
}

} // namespace lk::tuning
