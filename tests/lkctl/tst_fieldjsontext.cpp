// RequestText: requests built from field values typed as text (lkctl's command line), their
// round trip through FieldJson, refusals naming the field and its range, and the spec ranges
// against the builders.

#include "FieldJsonTestUtil.h"
#include "RequestText.h"
#include "protocol/ProtocolFields.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

using namespace lk::protocol;
using namespace lk::fieldjsontest;
using lk::lkctl::FieldBuildResult;
using lk::lkctl::FieldValues;
using lk::lkctl::RequestText;

namespace {
// A value every spec accepts: "cw" for a direction, the first word of a choice, else "1".
QString validText(const FieldSpec &s)
{
    if (s.kind == FieldKind::Direction)
        return QStringLiteral("cw");
    if (s.kind == FieldKind::Choice)
        return s.range.section(QLatin1Char('|'), 0, 0);
    return QStringLiteral("1");
}

// The specs of a command with valid values; a parameter write takes angle_pid's fields.
QList<FieldSpec> specsWithParam(Command command)
{
    QList<FieldSpec> specs = ProtocolFields::ofCommand(command);
    if (command == Command::WriteParamRam || command == Command::WriteParamRom)
        specs.append(ProtocolFields::ofParam(lk::protocol::ParamId::AnglePid));
    return specs;
}
} // namespace

class tst_FieldJsonText : public QObject {
    Q_OBJECT
private slots:
    void requestFieldsCoverEveryCommand();
    void roundTripThroughText_data();
    void roundTripThroughText();
    void buildRequestRefuses_data();
    void buildRequestRefuses();
    void specRangesMatchBuilders();
};

void tst_FieldJsonText::requestFieldsCoverEveryCommand()
{
    // Every command's request names exactly its specs plus, where scaled, "<field>_raw".
    QSet<int> seen;
    int canOnly = 0;
    for (const CommandInfo &info : CommandTable::all()) {
        if (info.canOnly) { // CAN V2.36's 0xC0/0xC1: lkctl encode builds RS485 frames
            ++canOnly;
            continue;
        }
        FieldValues values{{QStringLiteral("id"), QStringLiteral("1")}};
        QStringList expectedKeys;
        for (const FieldSpec &s : specsWithParam(info.command)) {
            values.insert(s.name, validText(s));
            expectedKeys << s.name;
            if (s.name == QLatin1String("param"))
                expectedKeys << QStringLiteral("param_id"); // the ParamID byte beside its name
            if (s.kind == FieldKind::Number)
                expectedKeys << QString(s.name).replace(QRegularExpression("_[a-z0-9]+$"),
                                                        QStringLiteral("_raw"));
        }
        const FieldBuildResult r = RequestText::build(info.command, values);
        QVERIFY2(r.ok(), qPrintable(r.message));
        QStringList keys = FieldJson::requestFields(*r.request).keys();
        keys.sort();
        expectedKeys.sort();
        QCOMPARE(keys, expectedKeys);
        seen.insert(int(info.command));
    }
    QCOMPARE(seen.size() + canOnly, CommandTable::kCount);
}

void tst_FieldJsonText::roundTripThroughText_data()
{
    addRequestRows(); // tst_FieldJson::requestFields' rows
}

void tst_FieldJsonText::roundTripThroughText()
{
    // Request -> fields -> text values (as typed on a command line) -> the same request.
    QFETCH(Request, request);
    const QJsonObject fields = FieldJson::requestFields(request);
    FieldValues values{{QStringLiteral("id"), QString::number(request.id)}};
    for (auto it = fields.begin(); it != fields.end(); ++it) {
        if (it.key().endsWith(QLatin1String("_raw")))
            continue;
        values.insert(it.key(), it.value().isString()
                                    ? it.value().toString()
                                    : QString::number(it.value().toDouble(), 'g', 17));
    }
    const FieldBuildResult r = RequestText::build(request.command, values);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.request->encode().toHex(' '), request.encode().toHex(' '));
}

void tst_FieldJsonText::buildRequestRefuses_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<FieldValues>("values");
    QTest::addColumn<QString>("field"); // empty: not a field's value (unknown name)
    QTest::addColumn<QString>("message");
    const auto id = [](FieldValues v) {
        v.insert(QStringLiteral("id"), QStringLiteral("1"));
        return v;
    };
    QTest::newRow("out of range") << "speed" << id({{"speed_dps", "21474836.48"}}) << "speed_dps"
                                  << "speed_dps must be in -21474836.48..21474836.47 dps "
                                     "(got 21474836.48)";
    QTest::newRow("torque over 32 A") << "torque" << id({{"iq_a", "32.01"}}) << "iq_a"
                                      << "iq_a must be in -32..32 A (got 32.01)";
    QTest::newRow("power") << "open_loop" << id({{"power", "851"}}) << "power"
                           << "power must be in -850..850 (got 851)";
    QTest::newRow("power not integer") << "open_loop" << id({{"power", "1.5"}}) << "power"
                                       << "power must be in -850..850 (got 1.5, not an integer)";
    QTest::newRow("not a number") << "speed" << id({{"speed_dps", "fast"}}) << "speed_dps"
                                  << "speed_dps must be in -21474836.48..21474836.47 dps "
                                     "(got 'fast', not a number)";
    QTest::newRow("nan") << "speed" << id({{"speed_dps", "nan"}}) << "speed_dps"
                         << "speed_dps must be in -21474836.48..21474836.47 dps (got nan)";
    QTest::newRow("missing") << "speed" << id({}) << "speed_dps"
                             << "speed_dps is missing; it must be in -21474836.48..21474836.47 dps";
    QTest::newRow("missing id") << "motor_off" << FieldValues{} << "id"
                                << "id is missing; it must be in 1..32";
    QTest::newRow("id 33") << "motor_off" << FieldValues{{"id", "33"}} << "id"
                           << "id must be in 1..32 (got 33)";
    QTest::newRow("id beyond int") << "motor_off" << FieldValues{{"id", "4294967297"}} << "id"
                                   << "id must be in 1..32 (got 4294967297)";
    QTest::newRow("pid gain beyond int") << "write_pid_ram"
                                         << id({{"angle_kp", "1"},
                                                {"angle_ki", "1"},
                                                {"speed_kp", "1"},
                                                {"speed_ki", "1"},
                                                {"iq_kp", "1"},
                                                {"iq_ki", "-4294967295"}})
                                         << "iq_ki"
                                         << "iq_ki must be in 0..255 (got -4294967295)";
    QTest::newRow("direction") << "single_position" << id({{"direction", "up"}, {"angle_deg", "1"}})
                               << "direction"
                               << "direction must be in cw|ccw (got 'up')";
    QTest::newRow("single angle 360")
        << "single_position" << id({{"direction", "cw"}, {"angle_deg", "360"}}) << "angle_deg"
        << "angle_deg must be in 0..359.99 deg (got 360)";
    QTest::newRow("negative max speed")
        << "multi_position_limited" << id({{"angle_deg", "1"}, {"max_speed_dps", "-1"}})
        << "max_speed_dps"
        << "max_speed_dps must be in 0..42949672.95 dps (got -1)";
    QTest::newRow("unknown field") << "speed" << id({{"speed_dps", "1"}, {"rpm", "5"}}) << ""
                                   << "unknown field rpm for speed (it takes: id, speed_dps)";
    QTest::newRow("max speed on the unlimited command")
        << "multi_position" << id({{"angle_deg", "1"}, {"max_speed_dps", "5"}}) << ""
        << "unknown field max_speed_dps for multi_position (it takes: id, angle_deg)";
    QTest::newRow("unknown command") << "spin" << id({}) << ""
                                     << "unknown command 'spin'";
}

void tst_FieldJsonText::buildRequestRefuses()
{
    QFETCH(QString, command);
    QFETCH(FieldValues, values);
    QFETCH(QString, field);
    QFETCH(QString, message);
    const FieldBuildResult r = RequestText::build(command, values);
    QVERIFY(!r.ok());
    QCOMPARE(r.message, message);
    QCOMPARE(r.fieldError ? r.fieldError->field : QString(), field);
}

void tst_FieldJsonText::specRangesMatchBuilders()
{
    // The ranges in the specs (help, "missing" messages) are the builders' own: push each
    // field out of range through the builder and compare what it says.
    const QStringList badIntegers{"-1", "256", "1001", "-1001", "65536"};
    int checked = 0;
    for (const CommandInfo &info : CommandTable::all()) {
        if (info.canOnly) // CAN V2.36's 0xC0/0xC1: lkctl encode/decode work on RS485 frames
            continue;
        QList<FieldSpec> specs = specsWithParam(info.command);
        specs.prepend(ProtocolFields::idSpec());
        FieldValues valid;
        for (const FieldSpec &s : specs)
            valid.insert(s.name, validText(s));
        QVERIFY2(RequestText::build(info.command, valid).ok(), info.name);
        for (const FieldSpec &s : specs) {
            if (s.kind == FieldKind::Direction || s.kind == FieldKind::Choice)
                continue; // not builder arguments: the builders take enums
            const QStringList bad =
                s.kind == FieldKind::Integer ? badIntegers : QStringList{"1e30", "-1e30"};
            bool refused = false;
            for (const QString &v : bad) {
                FieldValues values = valid;
                values.insert(s.name, v);
                const FieldBuildResult r = RequestText::build(info.command, values);
                if (r.ok())
                    continue;
                refused = true;
                QVERIFY(r.fieldError);
                QCOMPARE(r.fieldError->field, s.name);
                QCOMPARE(r.fieldError->range, s.range);
            }
            QVERIFY2(refused, qPrintable(s.name));
            ++checked;
        }
    }
    // 33 ids, 12 PID gains, accel, offset, power, iq, speed, 1 + 2 multi-position, 1 + 2
    // single-position (direction aside), 1 + 2 increment, 2 x 3 parameter gains (param and
    // brake action aside).
    QCOMPARE(checked, 33 + 12 + 5 + 3 + 3 + 3 + 6);
}

QTEST_APPLESS_MAIN(tst_FieldJsonText)
#include "tst_fieldjsontext.moc"
