// The field table (core/protocol/ProtocolFields) against its readers: the request builders'
// refusals at both ends of every wire range, the JSON writer's key order and reals, and the
// field lists of `lkctl encode` (RequestText).
#include "RequestText.h"
#include "protocol/ErrorFlags.h"
#include "protocol/FieldJson.h"
#include "protocol/ProtocolFields.h"

#include <QtCore/QJsonObject>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

#include <cmath>
#include <limits>

using namespace lk::protocol;
using lk::lkctl::FieldBuildResult;
using lk::lkctl::FieldValues;
using lk::lkctl::RequestText;

class tst_ProtocolFields : public QObject {
    Q_OBJECT
private slots:
    void rowsAreConsistent();
    void requestFieldsHaveOneRowEach();
    void rangesMatchBuilders();
    void jsonWriterFollowsTheTable();
    void writtenKeysAreInTheTable();
    void commandFieldsFollowTheTable();
};

namespace {

QString nameOf(const ProtocolField &f)
{
    return QString::fromLatin1(f.name);
}

/// The distinct names of the table in its order.
QStringList distinctNames()
{
    QStringList names;
    for (const ProtocolField &f : ProtocolFields::all()) {
        if (!names.contains(nameOf(f)))
            names << nameOf(f);
    }
    return names;
}

/// A command that takes `id` and, for a parameter's value, the parameter.
struct Owner {
    Command command = Command::MotorOff;
    std::optional<ParamId> param;
    QList<FieldSpec> specs; ///< all the fields of the request, id first
};

/// Fields of CAN V2.36's 0xC0/0xC1 only: lkctl encode/decode build RS485 frames, so no RS485
/// command owns them (tst_cancontrolparam checks their builders).
bool canOnlyField(FieldId id)
{
    return id >= FieldId::ControlParam;
}

std::optional<Owner> ownerOf(FieldId id)
{
    const auto has = [id](const QList<FieldSpec> &specs) {
        return std::any_of(specs.cbegin(), specs.cend(),
                           [id](const FieldSpec &s) { return s.id == id; });
    };
    for (const CommandInfo &info : CommandTable::all()) {
        if (info.canOnly) // CAN V2.36's 0xC0/0xC1: lkctl encode/decode work on RS485 frames
            continue;
        QList<FieldSpec> specs = ProtocolFields::ofCommand(info.command);
        specs.prepend(ProtocolFields::idSpec());
        if (info.command == Command::WriteParamRam) {
            for (const ParamInfo &p : ParamTable::all()) {
                const QList<FieldSpec> values = ProtocolFields::ofParam(p.id);
                if (has(values))
                    return Owner{info.command, p.id, specs + values};
            }
        }
        if (has(specs))
            return Owner{info.command, std::nullopt, specs};
    }
    return std::nullopt;
}

QString validText(const FieldSpec &s, const std::optional<ParamId> &param)
{
    if (s.kind == FieldKind::Direction)
        return QStringLiteral("cw");
    if (s.id == FieldId::Param && param)
        return ParamTable::name(*param);
    if (s.kind == FieldKind::Choice)
        return s.range.section(QLatin1Char('|'), 0, 0);
    return QStringLiteral("1");
}

QString text(const ProtocolField &f, double physical)
{
    return f.kind == FieldKind::Integer ? QString::number(qint64(physical))
                                        : QString::number(physical, 'g', 17);
}

/// One wire LSB beyond `wire` (outwards by `step`), or the next double where one LSB is
/// below the resolution of a double (multi-turn angles near 9e16 deg).
double beyond(const ProtocolField &f, qint64 wire, int step)
{
    const double edge = f.physical(wire);
    const double next = f.physical(wire + step);
    return next != edge ? next : std::nextafter(edge, step * std::numeric_limits<double>::max());
}

} // namespace

void tst_ProtocolFields::rowsAreConsistent()
{
    // Rows that share a name are neighbours and write it the same way.
    const QRegularExpression snake(QStringLiteral("^[a-z][a-z0-9]*(_[a-z0-9]+)*$"));
    const QList<ProtocolField> &rows = ProtocolFields::all();
    QSet<QString> closed;
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const ProtocolField &f = rows.at(i);
        QVERIFY2(snake.match(nameOf(f)).hasMatch(), f.name);
        QVERIFY2(!closed.contains(nameOf(f)), f.name); // appears again after other names
        if (i + 1 < rows.size() && nameOf(rows.at(i + 1)) == nameOf(f)) {
            QCOMPARE(rows.at(i + 1).real, f.real);
            QCOMPARE(QString::fromLatin1(rows.at(i + 1).unit), QString::fromLatin1(f.unit));
        } else {
            closed.insert(nameOf(f));
        }
        // lkctl's text mode shows a name once, from its first row (ReplyText).
        if (i > 0 && nameOf(rows.at(i - 1)) == nameOf(f))
            QVERIFY2(!f.label, f.name);
        if (f.label)
            QVERIFY2(qstrlen(f.label) > 0, f.name);
        QVERIFY2(f.scaleNum > 0 && f.scaleDen > 0, f.name);
        if (f.isRequestField()) {
            QVERIFY2(f.min <= f.max, f.name);
            // The parameter choices list their words at run time (ProtocolFields::spec).
            QVERIFY2(f.id == FieldId::Param || f.id == FieldId::ControlParam ||
                         qstrlen(f.range) > 0,
                     f.name);
        }
    }
    QCOMPARE(ProtocolFields::rank(QStringLiteral("no_such_field")), int(distinctNames().size()));
}

void tst_ProtocolFields::requestFieldsHaveOneRowEach()
{
    QSet<int> ids;
    for (const ProtocolField &f : ProtocolFields::all()) {
        if (!f.isRequestField())
            continue;
        QVERIFY2(!ids.contains(int(f.id)), f.name);
        ids.insert(int(f.id));
        QCOMPARE(ProtocolFields::field(f.id).name, f.name);
        QVERIFY2(canOnlyField(f.id) || ownerOf(f.id), f.name); // some command takes it
    }
    QCOMPARE(ids.size(), int(FieldId::ControlCurrentRampRaw)); // every FieldId but None
}

void tst_ProtocolFields::rangesMatchBuilders()
{
    // Each end of each wire range is accepted; one LSB beyond it is refused, naming the field
    // and the row's range text.
    int checked = 0;
    for (const ProtocolField &f : ProtocolFields::all()) {
        if (!f.isRequestField() || canOnlyField(f.id) ||
            (f.kind != FieldKind::Integer && f.kind != FieldKind::Number))
            continue;
        const Owner owner = *ownerOf(f.id);
        FieldValues valid;
        for (const FieldSpec &s : owner.specs)
            valid.insert(s.name, validText(s, owner.param));
        const auto build = [&](double physical) {
            FieldValues values = valid;
            values.insert(nameOf(f), text(f, physical));
            return RequestText::build(owner.command, values);
        };
        for (const auto &[edge, step] : {std::pair{f.min, -1}, std::pair{f.max, 1}}) {
            const FieldBuildResult in = build(f.physical(edge));
            QVERIFY2(in.ok(), qPrintable(nameOf(f) + QLatin1String(": ") + in.message));
            const FieldBuildResult out = build(beyond(f, edge, step));
            QVERIFY2(!out.ok(), qPrintable(nameOf(f) + QLatin1String(" beyond ") +
                                           text(f, beyond(f, edge, step))));
            QVERIFY2(out.fieldError, qPrintable(out.message));
            QCOMPARE(out.fieldError->field, nameOf(f));
            QCOMPARE(out.fieldError->range, QString::fromLatin1(f.range));
            QCOMPARE(ProtocolFields::spec(f.id).range, QString::fromLatin1(f.range));
            ++checked;
        }
    }
    QCOMPARE(checked, 2 * 30); // 33 request fields less the direction, action and param words
}

void tst_ProtocolFields::jsonWriterFollowsTheTable()
{
    // Every name at once (QJsonObject keeps them sorted): the line lists them in table order,
    // reals with a decimal point.
    const QStringList names = distinctNames();
    QJsonObject all;
    for (const QString &n : names)
        all.insert(n, 1);
    QStringList expected;
    for (const QString &n : names)
        expected << QStringLiteral("\"%1\":%2")
                        .arg(n, ProtocolFields::isReal(n) ? QStringLiteral("1.0")
                                                          : QStringLiteral("1"));
    QCOMPARE(QString::fromLatin1(FieldJson::toJsonLine(all)),
             QLatin1Char('{') + expected.join(QLatin1Char(',')) + QLatin1Char('}'));
}

void tst_ProtocolFields::writtenKeysAreInTheTable()
{
    // The names FieldJson writes for requests and for error flags all have a row (else they
    // would trail, sorted, after the known ones).
    const int unknown = int(distinctNames().size());
    for (const CommandInfo &info : CommandTable::all()) {
        if (info.canOnly) // CAN V2.36's 0xC0/0xC1: lkctl encode/decode work on RS485 frames
            continue;
        const std::optional<ParamId> param =
            info.command == Command::WriteParamRam || info.command == Command::WriteParamRom
                ? std::optional<ParamId>(ParamId::MaxAngleLow)
                : std::nullopt;
        QList<FieldSpec> specs = ProtocolFields::ofCommand(info.command);
        specs.prepend(ProtocolFields::idSpec());
        if (param)
            specs += ProtocolFields::ofParam(*param);
        FieldValues values;
        for (const FieldSpec &s : specs)
            values.insert(s.name, validText(s, param));
        const FieldBuildResult r = RequestText::build(info.command, values);
        QVERIFY2(r.ok(), qPrintable(r.message));
        for (const QString &key : FieldJson::requestFields(*r.request).keys())
            QVERIFY2(ProtocolFields::rank(key) < unknown, qPrintable(key));
    }
    for (Generation g : {Generation::V2_3, Generation::V2_35}) {
        for (const ErrorFlag &f : ErrorFlags::of(g))
            QVERIFY2(ProtocolFields::rank(QLatin1String(f.key)) < unknown, f.key);
    }
}

void tst_ProtocolFields::commandFieldsFollowTheTable()
{
    // `lkctl encode` lists a command's fields in CLI.md order: the table's.
    const auto ordered = [](const QList<FieldSpec> &specs) {
        for (qsizetype i = 1; i < specs.size(); ++i) {
            if (ProtocolFields::rank(specs.at(i - 1).name) > ProtocolFields::rank(specs.at(i).name))
                return false;
        }
        return true;
    };
    for (const CommandInfo &info : CommandTable::all()) {
        if (info.canOnly) // CAN V2.36's 0xC0/0xC1: lkctl encode/decode work on RS485 frames
            continue;
        QList<FieldSpec> specs = ProtocolFields::ofCommand(info.command);
        if (info.command == Command::WriteParamRam) {
            for (const ParamInfo &p : ParamTable::all())
                QVERIFY2(ordered(specs + ProtocolFields::ofParam(p.id)), p.name);
        }
        QVERIFY2(ordered(specs), info.name);
        for (const FieldSpec &s : specs)
            QCOMPARE(s.name, QString::fromLatin1(ProtocolFields::field(s.id).name));
    }
}

QTEST_APPLESS_MAIN(tst_ProtocolFields)
#include "tst_protocolfields.moc"
