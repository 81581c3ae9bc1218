#include "RequestText.h"

#include <protocol/ControlParameter.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QHash>
#include <QtCore/QStringList>

#include <cmath>
#include <limits>

namespace lk::lkctl {

using namespace protocol;

namespace {

/// Typed values of one request, parsed from text and checked for syntax (not for range).
struct ParsedFields {
    QHash<FieldId, qint64> integers;
    QHash<FieldId, double> numbers;
    QHash<FieldId, QString> choices;
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
        out.integers.insert(spec.id, v);
        return std::nullopt;
    }
    const double d = text.toDouble(&ok);
    if (!ok)
        return failField(spec, QStringLiteral("got '%1', not a number").arg(text));
    if (!std::isfinite(d) || std::fabs(d) >= 9.0e18)
        return failField(spec, QStringLiteral("got %1").arg(text));
    if (std::trunc(d) != d)
        return failField(spec, QStringLiteral("got %1, not an integer").arg(text));
    out.integers.insert(spec.id, static_cast<qint64>(d)); // "1e3" and "1000.0" are integers
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
        out.numbers.insert(spec.id, d);
        return std::nullopt;
    }
    case FieldKind::Choice: {
        const QString word = text.toLower();
        if (!spec.range.split(QLatin1Char('|')).contains(word))
            return failField(spec, QStringLiteral("got '%1'").arg(text));
        out.choices.insert(spec.id, word);
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
    QList<FieldSpec> specs = ProtocolFields::ofCommand(command);
    specs.prepend(ProtocolFields::idSpec());
    if (command == Command::WriteParamRam || command == Command::WriteParamRom) {
        const auto param = ParamTable::fromName(values.value(QStringLiteral("param")).toLower());
        if (param)
            specs.append(ProtocolFields::ofParam(*param));
    }
    if (command == Command::WriteControlParam) {
        const auto param =
            ControlParamTable::fromName(values.value(QStringLiteral("control_param")).toLower());
        if (param)
            specs.append(ProtocolFields::ofControlParam(*param));
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
    const ParamId param = *ParamTable::fromName(p.choices.value(FieldId::Param));
    const QList<FieldSpec> specs = ProtocolFields::ofParam(param);
    if (ParamTable::info(param).layout == ParamLayout::Pid)
        return build::writeParamPid(id, param, p.integers.value(specs[0].id),
                                    p.integers.value(specs[1].id), p.integers.value(specs[2].id),
                                    rom);
    return build::writeParam(id, param, p.numbers.value(specs[0].id), rom);
}

BuildResult buildControlParamWrite(int id, const ParsedFields &p)
{
    const ControlParamId param =
        *ControlParamTable::fromName(p.choices.value(FieldId::ControlParam));
    const QList<FieldSpec> specs = ProtocolFields::ofControlParam(param);
    if (ControlParamTable::info(param).layout == ControlParamLayout::Pid)
        return build::writeControlParamPid(id, param, p.integers.value(specs[0].id),
                                           p.integers.value(specs[1].id),
                                           p.integers.value(specs[2].id));
    return build::writeControlParam(id, param, p.numbers.value(specs[0].id));
}

BuildResult buildParsed(Command command, int id, const ParsedFields &p, const DecodeContext &drive)
{
    const auto num = [&p](FieldId field) { return p.numbers.value(field); };
    const auto in = [&p](FieldId field) { return p.integers.value(field); };
    switch (command) {
    case Command::WritePidRam:
    case Command::WritePidRom:
        return build::writePid(id, int(in(FieldId::AngleKp)), int(in(FieldId::AngleKi)),
                               int(in(FieldId::SpeedKp)), int(in(FieldId::SpeedKi)),
                               int(in(FieldId::IqKp)), int(in(FieldId::IqKi)),
                               command == Command::WritePidRom);
    case Command::WriteAccelRam:
        return build::writeAcceleration(id, in(FieldId::AccelDps2));
    case Command::WriteEncoderOffset:
        return build::writeEncoderOffset(id, in(FieldId::EncoderOffset));
    case Command::OpenLoop:
        return build::openLoop(id, in(FieldId::Power));
    case Command::Torque:
        return build::torque(id, num(FieldId::TorqueIqA), drive);
    case Command::Speed:
        return build::speed(id, num(FieldId::SpeedDps));
    case Command::MultiPosition:
        return build::multiPosition(id, num(FieldId::MultiAngleDeg));
    case Command::MultiPositionLimited:
        return build::multiPosition(id, num(FieldId::MultiAngleDeg), num(FieldId::MaxSpeedDps));
    case Command::SinglePosition:
        return build::singlePosition(id, p.direction, num(FieldId::SingleAngleDeg));
    case Command::SinglePositionLimited:
        return build::singlePosition(id, p.direction, num(FieldId::SingleAngleDeg),
                                     num(FieldId::MaxSpeedDps));
    case Command::IncrementPosition:
        return build::incrementPosition(id, num(FieldId::IncrementAngleDeg));
    case Command::IncrementPositionLimited:
        return build::incrementPosition(id, num(FieldId::IncrementAngleDeg),
                                        num(FieldId::MaxSpeedDps));
    case Command::ReadParam:
        return build::readParam(id, *ParamTable::fromName(p.choices.value(FieldId::Param)));
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return buildParamWrite(id, p, command == Command::WriteParamRom);
    case Command::ReadControlParam:
        return build::readControlParam(
            id, *ControlParamTable::fromName(p.choices.value(FieldId::ControlParam)));
    case Command::WriteControlParam:
        return buildControlParamWrite(id, p);
    case Command::Brake:
        return build::brake(id, brakeAction(p.choices.value(FieldId::Action)));
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
        const qint64 v = p.integers.value(s.id);
        if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
            return failField(s, QStringLiteral("got %1").arg(v));
    }
    return std::nullopt;
}

} // namespace

FieldBuildResult RequestText::build(Command command, const FieldValues &values,
                                    const DecodeContext &drive)
{
    ParsedFields parsed;
    if (auto failed = parseAll(command, values, parsed))
        return *failed;
    if (auto failed = checkIntArguments(command, values, parsed))
        return *failed;
    const BuildResult built =
        buildParsed(command, int(parsed.integers.value(FieldId::Id)), parsed, drive);
    FieldBuildResult r;
    if (built.ok()) {
        r.request = built.request;
    } else {
        r.fieldError = built.error;
        r.message = built.error.message();
    }
    return r;
}

FieldBuildResult RequestText::build(const QString &commandName, const FieldValues &values,
                                    const DecodeContext &drive)
{
    const std::optional<Command> command = CommandTable::fromName(commandName);
    if (!command)
        return failMessage(QStringLiteral("unknown command '%1'").arg(commandName));
    return build(*command, values, drive);
}

} // namespace lk::lkctl
