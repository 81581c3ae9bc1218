#include "ParameterFileText.h"

namespace lk::ui {

namespace {
QString number(double v)
{
    return QString::number(v, 'g', 15); // 2147483647 in full, 6553.5 as it is
}
} // namespace

QString ParameterFileText::expectation(const record::ParameterFileError &e)
{
    using ValueType = record::ParameterFileError::ValueType;
    switch (e.expected) {
    case ValueType::Integer:
        return tr("an integer in %1..%2").arg(number(e.min), number(e.max));
    case ValueType::Number:
        return tr("a number in %1..%2").arg(number(e.min), number(e.max));
    case ValueType::Text:
        return tr("text in quotes");
    case ValueType::Object:
        return tr("an object ({ ... })");
    }
    return QString();
}

QString ParameterFileText::describe(const record::ParameterFileError &e)
{
    using Kind = record::ParameterFileError::Kind;
    switch (e.kind) {
    case Kind::CannotRead:
        return tr("cannot read %1: %2").arg(e.path, e.detail);
    case Kind::TooLarge:
        return tr("%1 is too large to be a parameter file (more than %2 bytes)")
            .arg(e.path, number(e.max));
    case Kind::NotJson:
        return tr("not valid JSON (%1 at byte %2)").arg(e.detail).arg(e.offset);
    case Kind::NotObject:
        return tr("not a JSON object");
    case Kind::WrongFormat:
        return tr("not an LK Servo Studio parameter file (format is %1, not \"%2\")")
            .arg(e.found.isEmpty() ? tr("missing") : e.found,
                 QLatin1String(record::ParameterSet::kFormatName));
    case Kind::NewerVersion:
        return tr("written by a newer release (format version %1, this one reads up to %2)")
            .arg(e.found, number(e.max));
    case Kind::MissingKey:
        return tr("%1 is missing: it must be %2").arg(e.key, expectation(e));
    case Kind::UnknownKey:
        return tr("%1 is not a key of a parameter file (a typing error?)").arg(e.key);
    case Kind::DuplicateKey:
        return tr("%1 is given twice: which one is meant is not known").arg(e.key);
    case Kind::WrongType:
        return tr("%1 is %2: it must be %3").arg(e.key, e.found, expectation(e));
    case Kind::OutOfRange:
        return tr("%1 is %2, out of range: it must be %3").arg(e.key, e.found, expectation(e));
    case Kind::UnknownSeries:
        return tr("%1 is %2: it must be MS, MF, MG or MH").arg(e.key, e.found);
    case Kind::UnknownGeneration:
        return tr("%1 is %2: it must be \"v2.3\" or \"v2.35\"").arg(e.key, e.found);
    case Kind::BadTimestamp:
        return tr("%1 is %2: it must be a date and time such as \"2026-05-04T03:02:01.000Z\"")
            .arg(e.key, e.found);
    }
    return QString();
}

} // namespace lk::ui
