#include "StepRunFileText.h"

#include <QtCore/QFileInfo>

namespace lk::ui {

using Kind = tuning::StepRunFileError::Kind;
using Type = tuning::StepRunFileError::ValueType;

QString StepRunFileText::expectation(const tuning::StepRunFileError &e)
{
    switch (e.expected) {
    case Type::Integer:
        return tr("an integer in %1..%2").arg(e.min).arg(e.max);
    case Type::Number:
        return tr("a number in %1..%2").arg(e.min).arg(e.max);
    case Type::Text:
        return tr("text");
    case Type::Object:
        return tr("an object");
    case Type::Array:
        return tr("a list");
    }
    return {};
}

QString StepRunFileText::describe(const tuning::StepRunFileError &e)
{
    const QString file = QFileInfo(e.path).fileName();
    switch (e.kind) {
    case Kind::CannotRead:
        return tr("%1 cannot be read: %2").arg(file, e.detail);
    case Kind::TooLarge:
        return tr("%1 is larger than any run file (%2 bytes at most)").arg(file).arg(e.max);
    case Kind::NotJson:
        return tr("%1 is not JSON (%2, at byte %3)").arg(file, e.detail).arg(e.offset);
    case Kind::NotObject:
        return tr("%1 does not hold a JSON object").arg(file);
    case Kind::WrongFormat:
        return tr("%1 is not a step-run file (format %2)").arg(file, e.found);
    case Kind::NewerVersion:
        return tr("%1 was written by a newer release (version %2; this one reads up to %3)")
            .arg(file, e.found)
            .arg(e.max);
    case Kind::MissingKey:
        return tr("%1 lacks %2").arg(file, e.key);
    case Kind::UnknownKey:
        return tr("%1 has a key this format does not have: %2").arg(file, e.key);
    case Kind::DuplicateKey:
        return tr("%1 gives %2 twice").arg(file, e.key);
    case Kind::WrongType:
    case Kind::OutOfRange:
        return tr("%1: %2 is %3; it must be %4").arg(file, e.key, e.found, expectation(e));
    case Kind::BadText:
        return tr("%1: %2 holds %3, which means nothing there").arg(file, e.key, e.found);
    case Kind::EdgesNotAscending:
        return tr("%1: the steps in %2 are not in time order").arg(file, e.key);
    case Kind::MissingTrace:
        return tr("%1 names a trace file that cannot be read (%2): %3").arg(file, e.key, e.detail);
    case Kind::CsvBadHeader:
        return tr("%1, line 1: the header is %2, not time_s,value,effort").arg(file, e.found);
    case Kind::CsvBadRow:
        return tr("%1, line %2: %3 is not three cells").arg(file).arg(e.line).arg(e.found);
    case Kind::CsvBadNumber:
        return tr("%1, line %2, %3: %4 is not a number")
            .arg(file)
            .arg(e.line)
            .arg(e.column, e.found);
    case Kind::CsvTimeNotAscending:
        return tr("%1, line %2: time %3 is not after the line before")
            .arg(file)
            .arg(e.line)
            .arg(e.found);
    }
    return {};
}

} // namespace lk::ui
