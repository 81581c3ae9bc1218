#include "FleetData.h"

#include <fleet/FleetCatalog.h>
#include <fleet/IdMap.h>
#include <fleet/ParamDiff.h>
#include <fleet/RestorePlan.h>

#include <QtTest/QTest>

#include <functional>

using namespace lk;
using fleet::RestorePlan;
using fleettest::snapshot;
using protocol::Generation;
using protocol::Series;

class tst_RestorePlan : public QObject {
    Q_OBJECT
private slots:
    void refused_data();
    void refused();
    void changesAreTheDifferingRestorableValues();
    void writesCarryOnlyWhatChanges_data();
    void writesCarryOnlyWhatChanges();
    void can236WritesAreControlParamsInRamOnly();
    void can236ReadsAndDecodesControlParams();
    void canTargetIdentityIsCheckedFirst_data();
    void canTargetIdentityIsCheckedFirst();
    void diffMarksUnknownNeverEqual();
    void idListsAndMaps_data();
    void idListsAndMaps();
};

using Edit = std::function<void(fleet::DriveSnapshot &source, fleet::DriveSnapshot &target)>;
Q_DECLARE_METATYPE(Edit)

void tst_RestorePlan::refused_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<QString>("key");
    QTest::newRow("target not read") << Edit([](auto &, auto &t) {
        t.values.remove(QStringLiteral("iq_ki"));
        t.failure = QStringLiteral("read_pid: timeout");
    }) << QStringLiteral("read");
    QTest::newRow("target silent") << Edit([](auto &, auto &t) {
        t = fleet::DriveSnapshot();
        t.identity.id = 5;
        t.failure = QStringLiteral("read_model: timeout");
    }) << QStringLiteral("read");
    QTest::newRow("source incomplete")
        << Edit([](auto &s, auto &) { s.values.remove(QStringLiteral("accel_dps2")); })
        << QStringLiteral("source");
    QTest::newRow("other generation")
        << Edit([](auto &, auto &t) { t = snapshot(5, Generation::V2_35); })
        << QStringLiteral("generation");
    QTest::newRow("other link") << Edit([](auto &, auto &t) {
        t = snapshot(5, Generation::V2_3, Series::MF, 50, protocol::Link::Can);
    }) << QStringLiteral("link");
    QTest::newRow("other series") << Edit([](auto &, auto &t) { t.identity.series = Series::MG; })
                                  << QStringLiteral("series");
    QTest::newRow("series unknown")
        << Edit([](auto &s, auto &) { s.identity.series.reset(); }) << QStringLiteral("series");
    QTest::newRow("gain out of range")
        << Edit([](auto &s, auto &) { s.values[QStringLiteral("speed_ki")].value = 300; })
        << QStringLiteral("speed_ki");
}

void tst_RestorePlan::refused()
{
    QFETCH(Edit, edit);
    QFETCH(QString, key);
    fleet::DriveSnapshot source = snapshot(3, Generation::V2_3);
    fleet::DriveSnapshot target = snapshot(5, Generation::V2_3, Series::MF, 50);
    edit(source, target);
    const RestorePlan plan = RestorePlan::make(source, target);
    QVERIFY(plan.refusal);
    QCOMPARE(plan.refusal->key, key);
    QVERIFY(plan.changes.isEmpty());
}

void tst_RestorePlan::changesAreTheDifferingRestorableValues()
{
    const fleet::DriveSnapshot source = snapshot(3, Generation::V2_35);
    fleet::DriveSnapshot target = source;
    target.identity.id = 5;
    target.values[QStringLiteral("speed_kd")].value = 999;
    target.values[QStringLiteral("max_angle_raw")].value = 72000;
    target.values[QStringLiteral("encoder_offset")].value = 7; // the motor's own zero
    const RestorePlan plan = RestorePlan::make(source, target);
    QVERIFY(!plan.refusal);
    QCOMPARE(plan.changedKeys(), (QStringList{"speed_kd", "max_angle_raw"}));
    QCOMPARE(plan.changes.at(0).from, 999);
    QCOMPARE(plan.changes.at(0).to, source.values.value(QStringLiteral("speed_kd")).value);
}

void tst_RestorePlan::writesCarryOnlyWhatChanges_data()
{
    QTest::addColumn<int>("generation");
    QTest::addColumn<QStringList>("changed");
    QTest::addColumn<bool>("rom");
    QTest::addColumn<QStringList>("commands");
    QTest::newRow("v2.3 gain") << int(Generation::V2_3) << QStringList{"iq_kp"} << false
                               << QStringList{"write_pid_ram"};
    QTest::newRow("v2.3 accel") << int(Generation::V2_3) << QStringList{"accel_dps2"} << false
                                << QStringList{"write_accel_ram"};
    QTest::newRow("v2.3 rom: gains only, accel has no ROM command")
        << int(Generation::V2_3) << QStringList{"accel_dps2"} << true
        << QStringList{"write_pid_rom"};
    QTest::newRow("v2.35 one loop") << int(Generation::V2_35) << QStringList{"speed_kd"} << false
                                    << QStringList{"write_param_ram"};
    QTest::newRow("v2.35 max angle is a pair")
        << int(Generation::V2_35) << QStringList{"max_angle_raw"} << false
        << QStringList{"write_param_ram", "write_param_ram"};
    QTest::newRow("v2.35 rom writes every parameter")
        << int(Generation::V2_35) << QStringList{} << true
        << QStringList(9, QStringLiteral("write_param_rom"));
    QTest::newRow("encoder offset is never written")
        << int(Generation::V2_35) << QStringList{"encoder_offset"} << false << QStringList{};
}

void tst_RestorePlan::writesCarryOnlyWhatChanges()
{
    QFETCH(int, generation);
    QFETCH(QStringList, changed);
    QFETCH(bool, rom);
    QFETCH(QStringList, commands);
    const Generation g = Generation(generation);
    const QVector<fleet::ParamFrame> frames =
        fleet::FleetCatalog::writes(4, g, snapshot(3, g).valueMap(), changed, rom);
    QStringList sent;
    for (const fleet::ParamFrame &f : frames) {
        sent << protocol::CommandTable::name(f.request.command);
        QCOMPARE(int(f.request.id), 4);
    }
    QCOMPARE(sent, commands);
}

void tst_RestorePlan::can236WritesAreControlParamsInRamOnly()
{
    using protocol::Link;
    const fleet::DriveSnapshot source = snapshot(3, Generation::V2_35, Series::MF, 10, Link::Can);
    const fleet::ValueMap v = source.valueMap();
    // One changed gain writes its loop (Kp, Ki, Kd together); a limit its own parameter.
    const QVector<fleet::ParamFrame> frames = fleet::FleetCatalog::writes(
        4, Generation::V2_35, v, {"speed_ki", "max_speed_raw"}, false, Link::Can);
    QCOMPARE(frames.size(), 2);
    const auto *pid = std::get_if<protocol::ControlParameter>(&frames.at(0).request.payload);
    QVERIFY(pid);
    QCOMPARE(frames.at(0).request.command, protocol::Command::WriteControlParam);
    QCOMPARE(pid->paramId, quint8(0x0B));
    QCOMPARE(qint64(pid->pid()[0]), v.value("speed_kp"));
    QCOMPARE(qint64(pid->pid()[2]), v.value("speed_kd"));
    const auto *limit = std::get_if<protocol::ControlParameter>(&frames.at(1).request.payload);
    QCOMPARE(limit->paramId, quint8(0x20));
    QCOMPARE(qint64(limit->value()), v.value("max_speed_raw"));
    // There is no ROM: a ROM pass has no frame, whatever changed.
    QVERIFY(fleet::FleetCatalog::writes(4, Generation::V2_35, v, {"speed_ki"}, true, Link::Can)
                .isEmpty());
    QVERIFY(!fleet::FleetCatalog::hasRom(Generation::V2_35, Link::Can));
    QVERIFY(fleet::FleetCatalog::hasRom(Generation::V2_3, Link::Can));
    // The old CAN generation writes as V2.3 (0x31, 0x32 with --rom).
    const fleet::ValueMap old = snapshot(3, Generation::V2_3, Series::MG, 10, Link::Can).valueMap();
    QCOMPARE(fleet::FleetCatalog::writes(4, Generation::V2_3, old, {"iq_kp"}, true, Link::Can)
                 .value(0)
                 .request.command,
             protocol::Command::WritePidRom);
}

void tst_RestorePlan::can236ReadsAndDecodesControlParams()
{
    using protocol::Link;
    QStringList reads;
    for (const protocol::Request &r :
         fleet::FleetCatalog::reads(2, Generation::V2_35, Series::MF, Link::Can)) {
        const auto *c = std::get_if<protocol::ControlParamRead>(&r.payload);
        reads << (c ? QString::number(c->paramId, 16) : protocol::CommandTable::name(r.command));
    }
    QCOMPARE(reads, (QStringList{"a", "b", "c", "1e", "20", "22", "24", "26", "read_encoder"}));
    protocol::Reply reply{
        protocol::Command::ReadControlParam, 2,
        protocol::ControlParameter::ofValue(protocol::ControlParamId::InputTorqueLimit, 1500)};
    QCOMPARE(fleet::FleetCatalog::decode(reply), (fleet::ValueMap{{"max_torque", 1500}}));
    reply.payload =
        protocol::ControlParameter::ofPid(protocol::ControlParamId::CurrentPid, 1, 2, 3);
    QCOMPARE(fleet::FleetCatalog::decode(reply),
             (fleet::ValueMap{{"iq_kp", 1}, {"iq_ki", 2}, {"iq_kd", 3}}));
}

void tst_RestorePlan::canTargetIdentityIsCheckedFirst_data()
{
    QTest::addColumn<int>("generation");
    QTest::addColumn<int>("series");
    QTest::addColumn<QString>("key");
    QTest::newRow("declared as V2.36") << int(Generation::V2_35) << int(Series::MG) << "generation";
    QTest::newRow("declared as MF") << int(Generation::V2_3) << int(Series::MF) << "series";
    QTest::newRow("as the source") << int(Generation::V2_3) << int(Series::MG) << "read";
}

void tst_RestorePlan::canTargetIdentityIsCheckedFirst()
{
    // A target declared wrongly may well fail its read too: the refusal names the identity
    // that differs, the thing the user must correct; only a matching one is refused as unread.
    QFETCH(int, generation);
    QFETCH(int, series);
    QFETCH(QString, key);
    using protocol::Link;
    const fleet::DriveSnapshot source = snapshot(1, Generation::V2_3, Series::MG, 10, Link::Can);
    fleet::DriveSnapshot target =
        snapshot(3, Generation(generation), Series(series), 10, Link::Can);
    target.values.clear();
    target.failure = QStringLiteral("read_control_param: timeout");
    const RestorePlan plan = RestorePlan::make(source, target);
    QVERIFY(plan.refusal);
    QCOMPARE(plan.refusal->key, key);
    QVERIFY2(key == QLatin1String("read") || plan.refusal->reason.contains("(declared)"),
             qPrintable(plan.refusal->reason));
}

void tst_RestorePlan::diffMarksUnknownNeverEqual()
{
    fleet::DriveSnapshot a = snapshot(1, Generation::V2_3);
    fleet::DriveSnapshot b = snapshot(2, Generation::V2_3);
    b.values[QStringLiteral("iq_kp")].value = 1;
    b.values.remove(QStringLiteral("iq_ki"));
    QMap<QString, fleet::DiffRow::State> states;
    for (const fleet::DiffRow &r : fleet::ParamDiff::rows(a, b))
        states.insert(r.key, r.state());
    QCOMPARE(states.value(QStringLiteral("angle_kp")), fleet::DiffRow::State::Same);
    QCOMPARE(states.value(QStringLiteral("iq_kp")), fleet::DiffRow::State::Differs);
    QCOMPARE(states.value(QStringLiteral("iq_ki")), fleet::DiffRow::State::Unknown);
    const fleet::DriveSnapshot c = snapshot(3, Generation::V2_35);
    const auto mixed = fleet::ParamDiff::rows(a, c);
    const auto kd = std::find_if(mixed.begin(), mixed.end(),
                                 [](const fleet::DiffRow &r) { return r.key == "angle_kd"; });
    QVERIFY(kd != mixed.end());
    QVERIFY(!kd->a);
    QCOMPARE(kd->state(), fleet::DiffRow::State::Unknown);
}

void tst_RestorePlan::idListsAndMaps_data()
{
    QTest::addColumn<QString>("ids");
    QTest::addColumn<QString>("map");
    QTest::addColumn<bool>("ok");
    QTest::newRow("all") << "all"
                         << "3:5" << true;
    QTest::newRow("list and range") << "1,3-5"
                                    << "3:5,4:6" << true;
    QTest::newRow("id 0") << "0"
                          << "0:5" << false;
    QTest::newRow("id 33") << "1-33"
                           << "3:33" << false;
    QTest::newRow("backwards range") << "5-3"
                                     << "3" << false;
    QTest::newRow("two onto one") << "x"
                                  << "3:5,4:5" << false;
    QTest::newRow("one onto two") << "1--2"
                                  << "3:5,3:6" << false;
}

void tst_RestorePlan::idListsAndMaps()
{
    QFETCH(QString, ids);
    QFETCH(QString, map);
    QFETCH(bool, ok);
    QString error;
    QCOMPARE(fleet::IdMap::parseIds(ids, &error).has_value(), ok);
    QCOMPARE(fleet::IdMap::parseMap(map, &error).has_value(), ok);
    QVERIFY(ok || error.contains(map.section(',', -1)) || error.contains(map));
}

QTEST_GUILESS_MAIN(tst_RestorePlan)
#include "tst_restoreplan.moc"
