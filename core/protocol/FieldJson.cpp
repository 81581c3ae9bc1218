#include "FieldJson.h"

#include "ErrorFlags.h"
#include "RequestBuilder.h"

#include <QtCore/QHash>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonValue>
#include <QtCore/QLocale>
#include <QtCore/QStringList>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace lk::protocol {

namespace {

// ---- values -> JSON -------------------------------------------------------------------------

QJsonValue integer(qint64 v)
{
    return QJsonValue(v);
}

// Divisions by exact decimal powers give the double nearest to the decimal value, so 12345
// becomes 123.45 and not the 123.45000000000002 that 12345 * 0.01 gives.
QJsonValue centi(qint64 raw)
{
    return QJsonValue(static_cast<double>(raw) / 100.0);
}

QJsonObject pidFields(const PidGains &g)
{
    return {{QStringLiteral("angle_kp"), integer(g.angleKp)},
            {QStringLiteral("angle_ki"), integer(g.angleKi)},
            {QStringLiteral("speed_kp"), integer(g.speedKp)},
            {QStringLiteral("speed_ki"), integer(g.speedKi)},
            {QStringLiteral("iq_kp"), integer(g.iqKp)},
            {QStringLiteral("iq_ki"), integer(g.iqKi)}};
}

void addMaxSpeed(QJsonObject &o, const std::optional<quint32> &maxSpeedRaw)
{
    if (!maxSpeedRaw)
        return;
    o.insert(QStringLiteral("max_speed_dps"), centi(*maxSpeedRaw));
    o.insert(QStringLiteral("max_speed_raw"), integer(*maxSpeedRaw));
}

QJsonObject angleFields(qint64 angleRaw, const std::optional<quint32> &maxSpeedRaw)
{
    QJsonObject o{{QStringLiteral("angle_deg"), centi(angleRaw)},
                  {QStringLiteral("angle_raw"), integer(angleRaw)}};
    addMaxSpeed(o, maxSpeedRaw);
    return o;
}

QJsonObject paramHead(quint8 paramId)
{
    const ParamInfo *info = ParamTable::find(paramId);
    return {{QStringLiteral("param"),
             info ? QString::fromLatin1(info->name) : CommandTable::codeText(paramId)},
            {QStringLiteral("param_id"), integer(paramId)}};
}

// A parameter's value under the field names of V2.3 where they exist (angle_kp ... iq_ki,
// plus *_kd), so scripts read V2.35 gains like V2.3 ones.
QJsonObject parameterFields(const ParameterValue &v)
{
    QJsonObject o = paramHead(v.paramId);
    const std::optional<ParamId> id = v.id();
    if (!id) {
        QByteArray raw;
        for (quint8 b : v.bytes)
            raw.append(char(b));
        o.insert(QStringLiteral("value_bytes"), FieldJson::hexText(raw));
        return o;
    }
    switch (ParamTable::info(*id).layout) {
    case ParamLayout::Pid: {
        const QString loop = ParamTable::name(*id).chopped(4);
        o.insert(loop + QLatin1String("_kp"), integer(v.pidKp()));
        o.insert(loop + QLatin1String("_ki"), integer(v.pidKi()));
        o.insert(loop + QLatin1String("_kd"), integer(v.pidKd()));
        break;
    }
    case ParamLayout::HalfInt64:
        o.insert(QStringLiteral("max_angle_half_raw"), integer(v.asUInt32()));
        break;
    case ParamLayout::Int16:
        o.insert(*id == ParamId::MaxTorqueCurrent ? QStringLiteral("max_torque")
                                                  : QStringLiteral("current_ramp"),
                 integer(v.asInt16()));
        break;
    case ParamLayout::Int32:
        if (*id == ParamId::MaxSpeed) {
            o.insert(QStringLiteral("max_speed_dps"), centi(v.asInt32()));
            o.insert(QStringLiteral("max_speed_raw"), integer(v.asInt32()));
        } else {
            o.insert(QStringLiteral("speed_ramp_dps2"), integer(v.asInt32()));
        }
        break;
    }
    return o;
}

QString brakeActionName(BrakeAction a)
{
    switch (a) {
    case BrakeAction::Engage:
        return QStringLiteral("engage");
    case BrakeAction::Release:
        return QStringLiteral("release");
    case BrakeAction::Read:
        return QStringLiteral("read");
    }
    return QStringLiteral("0x%1").arg(quint8(a), 2, 16, QLatin1Char('0'));
}

struct RequestFieldVisitor {
    DecodeContext context;
    QJsonObject operator()(const NoPayload &) const { return {}; }
    QJsonObject operator()(const PidGains &g) const { return pidFields(g); }
    QJsonObject operator()(const Acceleration &a) const
    {
        return {{QStringLiteral("accel_dps2"), integer(a.dps2)}};
    }
    QJsonObject operator()(const EncoderOffset &e) const
    {
        return {{QStringLiteral("encoder_offset"), integer(e.offset)}};
    }
    QJsonObject operator()(const OpenLoopCommand &c) const
    {
        return {{QStringLiteral("power"), integer(c.power)}};
    }
    QJsonObject operator()(const TorqueCommand &c) const
    {
        // V2.3: 32 A per 2000 LSB, the integer product first, then one correctly rounded
        // division. V2.35: the drive's reply scale (a power of two, exact).
        const double a = context.generation == Generation::V2_3
                             ? c.iqRaw * 32.0 / 2000.0
                             : c.iqRaw * iqCommandAmpsPerLsb(context);
        return {{QStringLiteral("iq_a"), QJsonValue(a)},
                {QStringLiteral("iq_raw"), integer(c.iqRaw)}};
    }
    QJsonObject operator()(const SpeedCommand &c) const
    {
        return {{QStringLiteral("speed_dps"), centi(c.speedRaw)},
                {QStringLiteral("speed_raw"), integer(c.speedRaw)}};
    }
    QJsonObject operator()(const MultiPositionCommand &c) const
    {
        return angleFields(c.angleRaw, c.maxSpeedRaw);
    }
    QJsonObject operator()(const SinglePositionCommand &c) const
    {
        QJsonObject o = angleFields(c.angleRaw, c.maxSpeedRaw);
        o.insert(QStringLiteral("direction"), c.direction == SpinDirection::Clockwise
                                                  ? QStringLiteral("cw")
                                                  : QStringLiteral("ccw"));
        return o;
    }
    QJsonObject operator()(const IncrementPositionCommand &c) const
    {
        return angleFields(c.angleRaw, c.maxSpeedRaw);
    }
    QJsonObject operator()(const ParamRead &p) const { return paramHead(p.paramId); }
    QJsonObject operator()(const ParameterValue &v) const { return parameterFields(v); }
    QJsonObject operator()(const BrakeCommand &b) const
    {
        return {{QStringLiteral("action"), brakeActionName(b.action)}};
    }
};

QJsonObject modelFields(const ModelInfo &m)
{
    QJsonObject o{{QStringLiteral("driver_name"), m.driverName},
                  {QStringLiteral("motor_name"), m.motorName},
                  {QStringLiteral("hardware_version"), QJsonValue(m.hardwareVersion())},
                  {QStringLiteral("hardware_version_raw"), integer(m.hardwareRaw)},
                  {QStringLiteral("firmware_version"), QJsonValue(m.firmwareVersion())},
                  {QStringLiteral("firmware_version_raw"), integer(m.firmwareRaw)}};
    if (m.generation == Generation::V2_35) {
        // The 58-byte layout of newer firmware (ERRATA "Generations"); the motor version's
        // scale is undocumented, so only its wire value is given.
        o.insert(QStringLiteral("motor_id"), FieldJson::hexText(m.motorId));
        o.insert(QStringLiteral("motor_version_raw"), integer(m.motorVersionRaw));
    }
    return o;
}

struct ReplyFieldVisitor {
    QJsonObject operator()(const Acknowledged &) const { return {}; }
    QJsonObject operator()(const PidGains &g) const { return pidFields(g); }
    QJsonObject operator()(const Acceleration &a) const { return RequestFieldVisitor{{}}(a); }
    QJsonObject operator()(const EncoderReading &e) const
    {
        return {{QStringLiteral("encoder"), integer(e.encoder)},
                {QStringLiteral("encoder_raw"), integer(e.encoderRaw)},
                {QStringLiteral("encoder_offset"), integer(e.encoderOffset)}};
    }
    QJsonObject operator()(const EncoderOffset &e) const { return RequestFieldVisitor{{}}(e); }
    QJsonObject operator()(const ZeroWritten &z) const
    {
        if (!z.encoderOffset)
            return {};
        return {{QStringLiteral("encoder_offset"), integer(*z.encoderOffset)}};
    }
    QJsonObject operator()(const MultiTurnAngle &a) const { return angleFields(a.raw, {}); }
    QJsonObject operator()(const SingleTurnAngle &a) const { return angleFields(a.raw, {}); }
    QJsonObject operator()(const State1 &s) const
    {
        // Every flag the drive's generation names, true or false (V2.35.md section 5).
        QJsonObject o{{QStringLiteral("temperature_c"), integer(s.temperatureC)},
                      {QStringLiteral("error_state"), integer(s.errorState)}};
        for (const ErrorFlag &f : ErrorFlags::of(s.generation))
            o.insert(QLatin1String(f.key), bool(s.errorState & (1u << f.bit)));
        if (s.generation == Generation::V2_3) {
            o.insert(QStringLiteral("voltage_v"), QJsonValue(s.voltageRaw / 10.0));
            o.insert(QStringLiteral("voltage_raw"), integer(s.voltageRaw));
            return o;
        }
        o.insert(QStringLiteral("voltage_v"), QJsonValue(qint16(s.voltageRaw) / 100.0));
        o.insert(QStringLiteral("voltage_raw"), integer(qint16(s.voltageRaw)));
        o.insert(QStringLiteral("bus_current_a"), QJsonValue(s.busCurrentRaw / 100.0));
        o.insert(QStringLiteral("bus_current_raw"), integer(s.busCurrentRaw));
        const std::optional<bool> on = s.motorOn();
        o.insert(QStringLiteral("motor_on"), on ? QJsonValue(*on) : QJsonValue());
        o.insert(QStringLiteral("motor_state_raw"), integer(s.motorStateRaw));
        return o;
    }
    QJsonObject operator()(const State2 &s) const
    {
        QJsonObject o{{QStringLiteral("temperature_c"), integer(s.temperatureC)},
                      {QStringLiteral("speed_dps"), QJsonValue(double(s.speedDps))},
                      {QStringLiteral("encoder"), integer(s.encoder)}};
        if (s.isPower) {
            o.insert(QStringLiteral("power"), integer(s.torqueRaw));
        } else {
            o.insert(QStringLiteral("iq_a"), QJsonValue(s.iqA())); // 33/2048 is exact in binary
            o.insert(QStringLiteral("iq_raw"), integer(s.torqueRaw));
        }
        return o;
    }
    QJsonObject operator()(const State3 &s) const
    {
        return {{QStringLiteral("temperature_c"), integer(s.temperatureC)},
                {QStringLiteral("ia_a"), QJsonValue(s.iaA())},
                {QStringLiteral("ia_raw"), integer(s.iaRaw)},
                {QStringLiteral("ib_a"), QJsonValue(s.ibA())},
                {QStringLiteral("ib_raw"), integer(s.ibRaw)},
                {QStringLiteral("ic_a"), QJsonValue(s.icA())},
                {QStringLiteral("ic_raw"), integer(s.icRaw)}};
    }
    QJsonObject operator()(const ModelInfo &m) const { return modelFields(m); }
    QJsonObject operator()(const ParameterValue &v) const { return parameterFields(v); }
    QJsonObject operator()(const ParamWriteResult &r) const
    {
        QJsonObject o = paramHead(r.paramId);
        o.insert(QStringLiteral("success"), r.succeeded());
        o.insert(QStringLiteral("success_flag"), integer(r.flag));
        return o;
    }
    QJsonObject operator()(const BrakeState &b) const
    {
        return {{QStringLiteral("brake_released"), b.released()},
                {QStringLiteral("brake_raw"), integer(b.raw)}};
    }
};

// ---- JSON -> one line -----------------------------------------------------------------------

// Key order of CLI.md: the frame keys, then every field in the order of its field table. One
// order serves all commands because no two commands list shared fields in opposite orders.
int keyRank(const QString &key)
{
    static const QStringList order =
        QStringLiteral(
            "direction command code id fields error bytes "
            "temperature_c voltage_v voltage_raw bus_current_a bus_current_raw motor_on "
            "motor_state_raw error_state low_voltage over_voltage driver_over_temperature "
            "over_temperature motor_over_temperature over_current short_circuit stall "
            "input_timeout "
            "iq_a iq_raw power speed_dps speed_raw ia_a ia_raw ib_a ib_raw ic_a ic_raw "
            "encoder encoder_raw encoder_offset action param param_id "
            "angle_deg angle_raw max_speed_dps max_speed_raw "
            "angle_kp angle_ki angle_kd speed_kp speed_ki speed_kd iq_kp iq_ki iq_kd accel_dps2 "
            "max_torque max_angle_deg max_angle_raw max_angle_half_raw current_ramp "
            "speed_ramp_dps2 value_bytes "
            "success success_flag brake_released brake_raw "
            "driver_name motor_name hardware_version hardware_version_raw "
            "firmware_version firmware_version_raw motor_id motor_version_raw")
            .split(QLatin1Char(' '));
    static const QHash<QString, int> ranks = [] {
        QHash<QString, int> r;
        for (int i = 0; i < order.size(); ++i)
            r.insert(order.at(i), i);
        return r;
    }();
    return ranks.value(key, int(order.size())); // unknown keys after every known one
}

// Fields that hold physical (real) values. QJsonValue stores 100.0 as the integer 100, so the
// writer needs this list to print them as reals whatever their value.
bool isRealField(const QString &key)
{
    static const QStringList reals =
        QStringLiteral("speed_dps angle_deg max_speed_dps iq_a ia_a ib_a ic_a voltage_v "
                       "bus_current_a max_angle_deg hardware_version firmware_version")
            .split(QLatin1Char(' '));
    return reals.contains(key);
}

QByteArray numberText(const QJsonValue &v, bool real)
{
    const double d = v.toDouble();
    if (!std::isfinite(d))
        return QByteArrayLiteral("null"); // JSON has no NaN; no field ever produces one
    const QVariant var = v.toVariant();
    if (!real && var.typeId() == QMetaType::LongLong)
        return QByteArray::number(v.toInteger());
    QByteArray text = QByteArray::number(d, 'g', QLocale::FloatingPointShortest);
    if (real && !text.contains('.') && !text.contains('e'))
        text += ".0";
    return text;
}

QByteArray stringText(const QString &s)
{
    // Keys, names and hex are plain ASCII: quote them directly.
    const bool plain = std::all_of(s.cbegin(), s.cend(), [](QChar c) {
        return c.unicode() >= 0x20 && c.unicode() < 0x7F && c != QLatin1Char('"') &&
               c != QLatin1Char('\\');
    });
    if (plain)
        return '"' + s.toLatin1() + '"';
    // Anything else: let QJsonDocument escape it in a one-element array, brackets dropped.
    const QByteArray a = QJsonDocument(QJsonArray{s}).toJson(QJsonDocument::Compact);
    return a.mid(1, a.size() - 2);
}

void writeObject(QByteArray &out, const QJsonObject &o);

void writeValue(QByteArray &out, const QString &key, const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Bool:
        out += v.toBool() ? "true" : "false";
        break;
    case QJsonValue::Double:
        out += numberText(v, isRealField(key));
        break;
    case QJsonValue::String:
        out += stringText(v.toString());
        break;
    case QJsonValue::Array: {
        out += '[';
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < a.size(); ++i) {
            if (i > 0)
                out += ',';
            writeValue(out, key, a.at(i));
        }
        out += ']';
        break;
    }
    case QJsonValue::Object:
        writeObject(out, v.toObject());
        break;
    case QJsonValue::Null:
    case QJsonValue::Undefined:
        out += "null";
        break;
    }
}

void writeObject(QByteArray &out, const QJsonObject &o)
{
    // Rank each key once; keys() is sorted, so unknown keys stay sorted after the known ones.
    std::vector<std::pair<int, QString>> keys;
    keys.reserve(size_t(o.size()));
    for (const QString &k : o.keys())
        keys.emplace_back(keyRank(k), k);
    std::stable_sort(keys.begin(), keys.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    out += '{';
    for (size_t i = 0; i < keys.size(); ++i) {
        if (i > 0)
            out += ',';
        out += stringText(keys[i].second);
        out += ':';
        writeValue(out, keys[i].second, o.value(keys[i].second));
    }
    out += '}';
}

// ---- text fields -> request -----------------------------------------------------------------

const QString kCentiSigned32 = QStringLiteral("-21474836.48..21474836.47");
const QString kMaxSpeedRange = QStringLiteral("0..42949672.95 dps");

QList<FieldSpec> pidSpecs()
{
    QList<FieldSpec> specs;
    for (const char *name : {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"})
        specs.append({QString::fromLatin1(name), FieldKind::Integer, QStringLiteral("0..255")});
    return specs;
}

FieldSpec directionSpec()
{
    return {QStringLiteral("direction"), FieldKind::Direction, QStringLiteral("cw|ccw")};
}

FieldSpec maxSpeedSpec()
{
    return {QStringLiteral("max_speed_dps"), FieldKind::Number, kMaxSpeedRange};
}

FieldSpec singleAngleSpec()
{
    return {QStringLiteral("angle_deg"), FieldKind::Number, QStringLiteral("0..359.99 deg")};
}

FieldSpec incrementSpec()
{
    return {QStringLiteral("angle_deg"), FieldKind::Number,
            kCentiSigned32 + QStringLiteral(" deg")};
}

FieldSpec multiAngleSpec()
{
    return {QStringLiteral("angle_deg"), FieldKind::Number, QStringLiteral("-9e16..9e16 deg")};
}

FieldSpec paramSpec()
{
    QStringList names;
    for (const ParamInfo &p : ParamTable::all())
        names << QString::fromLatin1(p.name);
    return {QStringLiteral("param"), FieldKind::Choice, names.join(QLatin1Char('|'))};
}

/// Typed values of one request, parsed from text and checked for syntax (not for range).
struct ParsedFields {
    QMap<QString, qint64> integers;
    QMap<QString, double> numbers;
    QMap<QString, QString> choices;
    SpinDirection direction = SpinDirection::Clockwise;
};

FieldBuildResult failField(const FieldSpec &spec, const QString &problem)
{
    FieldBuildResult r;
    r.fieldError = FieldError{spec.name, spec.range, problem};
    r.message = r.fieldError->message();
    return r;
}

FieldBuildResult failMessage(const QString &message)
{
    FieldBuildResult r;
    r.message = message;
    return r;
}

std::optional<FieldBuildResult> parseInteger(const FieldSpec &spec, const QString &text,
                                             ParsedFields &out)
{
    bool ok = false;
    const qint64 v = text.toLongLong(&ok, 10);
    if (ok) {
        out.integers.insert(spec.name, v);
        return std::nullopt;
    }
    const double d = text.toDouble(&ok);
    if (!ok)
        return failField(spec, QStringLiteral("got '%1', not a number").arg(text));
    if (!std::isfinite(d) || std::fabs(d) >= 9.0e18)
        return failField(spec, QStringLiteral("got %1").arg(text));
    if (std::trunc(d) != d)
        return failField(spec, QStringLiteral("got %1, not an integer").arg(text));
    out.integers.insert(spec.name, static_cast<qint64>(d)); // "1e3" and "1000.0" are integers
    return std::nullopt;
}

std::optional<FieldBuildResult> parseField(const FieldSpec &spec, const QString &raw,
                                           ParsedFields &out)
{
    const QString text = raw.trimmed();
    switch (spec.kind) {
    case FieldKind::Integer:
        return parseInteger(spec, text, out);
    case FieldKind::Number: {
        bool ok = false;
        const double d = text.toDouble(&ok); // NaN and infinities reach the builder: it refuses
        if (!ok)
            return failField(spec, QStringLiteral("got '%1', not a number").arg(text));
        out.numbers.insert(spec.name, d);
        return std::nullopt;
    }
    case FieldKind::Choice: {
        const QString word = text.toLower();
        if (!spec.range.split(QLatin1Char('|')).contains(word))
            return failField(spec, QStringLiteral("got '%1'").arg(text));
        out.choices.insert(spec.name, word);
        return std::nullopt;
    }
    case FieldKind::Direction: {
        const QString d = text.toLower();
        if (d != QLatin1String("cw") && d != QLatin1String("ccw"))
            return failField(spec, QStringLiteral("got '%1'").arg(text));
        out.direction =
            d == QLatin1String("cw") ? SpinDirection::Clockwise : SpinDirection::CounterClockwise;
        return std::nullopt;
    }
    }
    return std::nullopt;
}

/// The fields of `command` given these values: a parameter write's value fields depend on
/// which parameter it names.
QList<FieldSpec> specsFor(Command command, const FieldValues &values)
{
    QList<FieldSpec> specs = FieldJson::requestFieldSpecs(command);
    specs.prepend(FieldJson::idSpec());
    if (command == Command::WriteParamRam || command == Command::WriteParamRom) {
        const auto param = ParamTable::fromName(values.value(QStringLiteral("param")).toLower());
        if (param)
            specs.append(FieldJson::paramFieldSpecs(*param));
    }
    return specs;
}

/// Parse every field a command takes (and the id); refuse unknown and missing ones.
std::optional<FieldBuildResult> parseAll(Command command, const FieldValues &values,
                                         ParsedFields &out)
{
    const QList<FieldSpec> specs = specsFor(command, values);
    QStringList names;
    for (const FieldSpec &s : specs)
        names.append(s.name);
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        if (!names.contains(it.key()))
            return failMessage(
                QStringLiteral("unknown field %1 for %2 (it takes: %3)")
                    .arg(it.key(), CommandTable::name(command), names.join(QStringLiteral(", "))));
    }
    for (const FieldSpec &s : specs) {
        if (!values.contains(s.name)) {
            FieldBuildResult r = failField(s, QStringLiteral("missing"));
            r.message = QStringLiteral("%1 is missing; it must be in %2").arg(s.name, s.range);
            return r;
        }
        if (auto failed = parseField(s, values.value(s.name), out))
            return failed;
    }
    return std::nullopt;
}

BrakeAction brakeAction(const QString &word)
{
    if (word == QLatin1String("engage"))
        return BrakeAction::Engage;
    return word == QLatin1String("release") ? BrakeAction::Release : BrakeAction::Read;
}

BuildResult buildParamWrite(int id, const ParsedFields &p, bool rom)
{
    const ParamId param = *ParamTable::fromName(p.choices.value(QStringLiteral("param")));
    const QList<FieldSpec> specs = FieldJson::paramFieldSpecs(param);
    if (ParamTable::info(param).layout == ParamLayout::Pid)
        return build::writeParamPid(id, param, p.integers.value(specs[0].name),
                                    p.integers.value(specs[1].name),
                                    p.integers.value(specs[2].name), rom);
    return build::writeParam(id, param, p.numbers.value(specs[0].name), rom);
}

BuildResult buildParsed(Command command, int id, const ParsedFields &p)
{
    const auto num = [&p](const char *name) { return p.numbers.value(QLatin1String(name)); };
    const auto in = [&p](const char *name) { return p.integers.value(QLatin1String(name)); };
    switch (command) {
    case Command::WritePidRam:
    case Command::WritePidRom:
        return build::writePid(id, int(in("angle_kp")), int(in("angle_ki")), int(in("speed_kp")),
                               int(in("speed_ki")), int(in("iq_kp")), int(in("iq_ki")),
                               command == Command::WritePidRom);
    case Command::WriteAccelRam:
        return build::writeAcceleration(id, in("accel_dps2"));
    case Command::WriteEncoderOffset:
        return build::writeEncoderOffset(id, in("encoder_offset"));
    case Command::OpenLoop:
        return build::openLoop(id, in("power"));
    case Command::Torque:
        return build::torque(id, num("iq_a"));
    case Command::Speed:
        return build::speed(id, num("speed_dps"));
    case Command::MultiPosition:
        return build::multiPosition(id, num("angle_deg"));
    case Command::MultiPositionLimited:
        return build::multiPosition(id, num("angle_deg"), num("max_speed_dps"));
    case Command::SinglePosition:
        return build::singlePosition(id, p.direction, num("angle_deg"));
    case Command::SinglePositionLimited:
        return build::singlePosition(id, p.direction, num("angle_deg"), num("max_speed_dps"));
    case Command::IncrementPosition:
        return build::incrementPosition(id, num("angle_deg"));
    case Command::IncrementPositionLimited:
        return build::incrementPosition(id, num("angle_deg"), num("max_speed_dps"));
    case Command::ReadParam:
        return build::readParam(id,
                                *ParamTable::fromName(p.choices.value(QStringLiteral("param"))));
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return buildParamWrite(id, p, command == Command::WriteParamRom);
    case Command::Brake:
        return build::brake(id, brakeAction(p.choices.value(QStringLiteral("action"))));
    default:
        return build::plain(command, id);
    }
}

/// The builders take int for id and PID gains: a value beyond int is refused here, with the
/// field's own range, rather than being narrowed into range by a cast.
std::optional<FieldBuildResult> checkIntArguments(Command command, const FieldValues &values,
                                                  const ParsedFields &p)
{
    for (const FieldSpec &s : specsFor(command, values)) {
        if (s.kind != FieldKind::Integer)
            continue;
        const qint64 v = p.integers.value(s.name);
        if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
            return failField(s, QStringLiteral("got %1").arg(v));
    }
    return std::nullopt;
}

} // namespace

// ---- FieldJson ------------------------------------------------------------------------------

QJsonObject FieldJson::requestFields(const Request &request, const DecodeContext &context)
{
    return std::visit(RequestFieldVisitor{context}, request.payload);
}

QJsonObject FieldJson::replyFields(const Reply &reply)
{
    return std::visit(ReplyFieldVisitor{}, reply.payload);
}

std::optional<QJsonObject> FieldJson::frameObject(const Frame &frame, FrameDirection direction,
                                                  const DecodeContext &context)
{
    QJsonObject fields;
    if (direction == FrameDirection::Reply) {
        const ReplyDecodeResult r = decodeReply(frame, context);
        if (!r.reply)
            return std::nullopt;
        fields = replyFields(*r.reply);
    } else {
        // An echo carries the request's bytes: its fields are the values written.
        const RequestDecodeResult r = decodeRequest(frame);
        if (!r.request)
            return std::nullopt;
        fields = requestFields(*r.request, context);
    }
    return QJsonObject{{QStringLiteral("direction"), QLatin1String(directionName(direction))},
                       {QStringLiteral("command"), CommandTable::name(Command(frame.command))},
                       {QStringLiteral("code"), CommandTable::codeText(frame.command)},
                       {QStringLiteral("id"), integer(frame.id)},
                       {QStringLiteral("fields"), fields}};
}

QJsonObject FieldJson::errorObject(ParseError error, const QByteArray &bytes)
{
    return {{QStringLiteral("error"), QLatin1String(parseErrorName(error))},
            {QStringLiteral("bytes"), hexText(bytes)}};
}

QJsonObject FieldJson::eventObject(const ParseEvent &event, const DecodeContext &context)
{
    if (!event.isFrame)
        return errorObject(event.error, event.bytes);
    if (auto o = frameObject(event.frame, event.direction, context))
        return *o;
    // The parser takes the direction from the same command table the decoders use, so this
    // is not expected; should they ever disagree, the frame is reported, not dropped.
    return errorObject(ParseError::BadLength, event.bytes);
}

bool FieldJson::isError(const QJsonObject &object)
{
    return object.contains(QStringLiteral("error"));
}

QByteArray FieldJson::toJsonLine(const QJsonObject &object)
{
    QByteArray out;
    out.reserve(160);
    writeObject(out, object);
    return out;
}

QString FieldJson::hexText(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

FieldSpec FieldJson::idSpec()
{
    return {QStringLiteral("id"), FieldKind::Integer, QStringLiteral("1..32")};
}

QList<FieldSpec> FieldJson::requestFieldSpecs(Command command)
{
    switch (command) {
    case Command::WritePidRam:
    case Command::WritePidRom:
        return pidSpecs();
    case Command::WriteAccelRam:
        return {{QStringLiteral("accel_dps2"), FieldKind::Integer,
                 QStringLiteral("0..2147483647 dps/s")}};
    case Command::WriteEncoderOffset:
        return {{QStringLiteral("encoder_offset"), FieldKind::Integer, QStringLiteral("0..65535")}};
    case Command::OpenLoop:
        return {{QStringLiteral("power"), FieldKind::Integer, QStringLiteral("-850..850")}};
    case Command::Torque:
        return {{QStringLiteral("iq_a"), FieldKind::Number, QStringLiteral("-32..32 A")}};
    case Command::Speed:
        return {{QStringLiteral("speed_dps"), FieldKind::Number,
                 kCentiSigned32 + QStringLiteral(" dps")}};
    case Command::MultiPosition:
        return {multiAngleSpec()};
    case Command::MultiPositionLimited:
        return {multiAngleSpec(), maxSpeedSpec()};
    case Command::SinglePosition:
        return {directionSpec(), singleAngleSpec()};
    case Command::SinglePositionLimited:
        return {directionSpec(), singleAngleSpec(), maxSpeedSpec()};
    case Command::IncrementPosition:
        return {incrementSpec()};
    case Command::IncrementPositionLimited:
        return {incrementSpec(), maxSpeedSpec()};
    case Command::ReadParam:
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return {paramSpec()};
    case Command::Brake:
        return {
            {QStringLiteral("action"), FieldKind::Choice, QStringLiteral("engage|release|read")}};
    default:
        return {};
    }
}

QList<FieldSpec> FieldJson::paramFieldSpecs(ParamId param)
{
    switch (param) {
    case ParamId::AnglePid:
    case ParamId::SpeedPid:
    case ParamId::CurrentPid: {
        const QString loop = ParamTable::name(param).chopped(4);
        QList<FieldSpec> specs;
        for (const char *k : {"_kp", "_ki", "_kd"})
            specs.append({loop + QLatin1String(k), FieldKind::Integer, QStringLiteral("0..65535")});
        return specs;
    }
    case ParamId::MaxTorqueCurrent:
        return {{QStringLiteral("max_torque"), FieldKind::Number, QStringLiteral("0..2048")}};
    case ParamId::MaxSpeed:
        return {{QStringLiteral("max_speed_dps"), FieldKind::Number,
                 QStringLiteral("0..21474836.47 dps")}};
    case ParamId::MaxAngleLow:
    case ParamId::MaxAngleHigh:
        return {
            {QStringLiteral("max_angle_deg"), FieldKind::Number, QStringLiteral("0..9e16 deg")}};
    case ParamId::CurrentRamp:
        return {{QStringLiteral("current_ramp"), FieldKind::Number, QStringLiteral("0..32767")}};
    case ParamId::SpeedRamp:
        return {{QStringLiteral("speed_ramp_dps2"), FieldKind::Number,
                 QStringLiteral("0..2147483647 dps/s")}};
    }
    return {};
}

FieldBuildResult FieldJson::buildRequest(Command command, const FieldValues &values)
{
    ParsedFields parsed;
    if (auto failed = parseAll(command, values, parsed))
        return *failed;
    if (auto failed = checkIntArguments(command, values, parsed))
        return *failed;
    const BuildResult built =
        buildParsed(command, int(parsed.integers.value(QStringLiteral("id"))), parsed);
    FieldBuildResult r;
    if (built.ok()) {
        r.request = built.request;
    } else {
        r.fieldError = built.error;
        r.message = built.error.message();
    }
    return r;
}

FieldBuildResult FieldJson::buildRequest(const QString &commandName, const FieldValues &values)
{
    const std::optional<Command> command = CommandTable::fromName(commandName);
    if (!command)
        return failMessage(QStringLiteral("unknown command '%1'").arg(commandName));
    return buildRequest(*command, values);
}

} // namespace lk::protocol
