#include "StepTraceCsv.h"

#include <record/CsvWriter.h>

#include <cmath>

namespace lk::tuning {

namespace {

using Kind = StepRunFileError::Kind;

// Microseconds and millionths of a unit: finer than any bus timestamp or encoder step.
constexpr int kDecimals = 6;

bool refuse(StepRunFileError *error, Kind kind, int line, const QString &column = {},
            const QByteArray &found = {})
{
    if (error) {
        error->kind = kind;
        error->line = line;
        error->column = column;
        error->found = QString::fromUtf8(found);
    }
    return false;
}

/// A finite number in the C locale; nullopt for anything else (empty included).
std::optional<double> number(const QByteArray &cell)
{
    bool ok = false;
    const double v = cell.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

} // namespace

QByteArray StepTraceCsv::header()
{
    return QByteArrayLiteral("time_s,value,effort\n");
}

double StepTraceCsv::fileTime(double time, double origin)
{
    return record::CsvWriter::formatNumber(time - origin, kDecimals).toDouble();
}

QByteArray StepTraceCsv::rows(const StepTrace &trace, double origin)
{
    QByteArray text;
    text.reserve(trace.size() * 40);
    for (int i = 0; i < trace.size(); ++i) {
        text += record::CsvWriter::formatNumber(trace.time[i] - origin, kDecimals);
        text += ',';
        text += record::CsvWriter::formatNumber(trace.value[i], kDecimals);
        text += ',';
        text +=
            record::CsvWriter::formatNumber(trace.effort.value(i, StepTrace::missing()), kDecimals);
        text += '\n';
    }
    return text;
}

bool StepTraceCsv::read(QIODevice &device, StepTrace &trace, StepRunFileError *error)
{
    const QByteArray first = device.readLine().trimmed();
    if (first + '\n' != header())
        return refuse(error, Kind::CsvBadHeader, 1, {}, first);
    int line = 1;
    while (!device.atEnd()) {
        const QByteArray text = device.readLine().trimmed();
        ++line;
        if (text.isEmpty() && device.atEnd())
            break; // a final empty line
        const QList<QByteArray> cells = text.split(',');
        if (cells.size() != 3)
            return refuse(error, Kind::CsvBadRow, line, {}, text);
        const std::optional<double> t = number(cells[0]);
        if (!t)
            return refuse(error, Kind::CsvBadNumber, line, QStringLiteral("time_s"), cells[0]);
        const std::optional<double> v = number(cells[1]);
        if (!v)
            return refuse(error, Kind::CsvBadNumber, line, QStringLiteral("value"), cells[1]);
        const bool noEffort = cells[2].trimmed().isEmpty();
        const std::optional<double> e = noEffort ? StepTrace::missing() : number(cells[2]);
        if (!e)
            return refuse(error, Kind::CsvBadNumber, line, QStringLiteral("effort"), cells[2]);
        if (trace.size() > 0 && *t < trace.time.last())
            return refuse(error, Kind::CsvTimeNotAscending, line, QStringLiteral("time_s"),
                          cells[0]);
        trace.append(*t, *v, *e);
    }
    return true;
}

} // namespace lk::tuning
