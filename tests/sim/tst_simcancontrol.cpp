// A simulated CAN V2.36 drive's control parameters (0xC0/0xC1, docs/CAN.md section 4.1): read
// from the drive's RAM, written to RAM only (a power cycle brings back ROM, nothing writes
// flash), used by the same physics at once; silent where the dialect has none.

#include "SimTestUtil.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <protocol/LinkCodec.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimCanFront.h>

#include <QtTest/QTest>

namespace proto = lk::protocol;
namespace can = lk::protocol::can;
using lk::sim::SimBus;
using lk::sim::SimCanFront;
using lk::sim::SimDriveModel;
using lk::sim::SimReply;
using proto::Command;
using proto::ControlParameter;
using proto::ControlParamId;
using proto::Generation;

namespace {
constexpr int kV236 = 2;
constexpr int kOld = 1;
const proto::DecodeContext kCtx{proto::Series::MF, Generation::V2_35, proto::Link::Can};

QByteArray record(const proto::BuildResult &b)
{
    if (!b.ok())
        qFatal("test request refused: %s", qPrintable(b.error.message()));
    const proto::WireEncodeResult w = proto::encodeRequest(*b.request, kCtx);
    if (!w.ok())
        qFatal("test request refused: %s", qPrintable(w.error.message()));
    return w.bytes;
}

std::optional<ControlParameter> valueOf(const QList<SimReply> &out)
{
    if (out.size() != 1)
        return std::nullopt;
    std::optional<ControlParameter> v;
    proto::CanRecordParser parser;
    parser.feed(out[0].bytes, [&](const proto::ParseEvent &e) {
        if (!e.isFrame)
            return;
        const auto r = proto::decodeReply(e.frame, kCtx).reply;
        if (r)
            v = std::get<ControlParameter>(r->payload);
    });
    return v;
}
} // namespace

class tst_SimCanControl : public QObject {
    Q_OBJECT
private slots:
    void init();
    void readsWhatRamHolds_data();
    void readsWhatRamHolds();
    void writeChangesRamOnly();
    void physicsUsesTheWrittenGains();
    void refusedWriteAnswersTheValueKept();
    void silentWhereTheDialectHasNone();

private:
    std::optional<ControlParameter> ask(const proto::BuildResult &b, double t = 0.0)
    {
        return valueOf(m_front->receive(record(b), t));
    }
    lk::sim::SimDrive &drive() { return *m_bus->drive(kV236); }

    std::unique_ptr<SimBus> m_bus;
    std::unique_ptr<SimCanFront> m_front;
    int m_romWrites = 0;
};

void tst_SimCanControl::init()
{
    m_bus = std::make_unique<SimBus>();
    SimDriveModel old = SimDriveModel::forSeries(proto::Series::MG);
    SimDriveModel v236 = SimDriveModel::forSeries(proto::Series::MF);
    v236.generation = Generation::V2_35;
    QVERIFY(m_bus->addDrive(kOld, old));
    QVERIFY(m_bus->addDrive(kV236, v236));
    m_romWrites = 0;
    drive().setRomWrittenHandler(
        [this](int, proto::Series, const lk::sim::SimRom &) { ++m_romWrites; });
    m_front = std::make_unique<SimCanFront>(*m_bus);
}

void tst_SimCanControl::readsWhatRamHolds_data()
{
    QTest::addColumn<int>("param");
    for (const proto::ControlParamInfo &p : proto::ControlParamTable::all())
        QTest::newRow(p.name) << int(p.id);
}

void tst_SimCanControl::readsWhatRamHolds()
{
    QFETCH(int, param);
    const auto id = ControlParamId(param);
    const auto v = ask(proto::build::readControlParam(kV236, id));
    QVERIFY(v);
    QCOMPARE(v->paramId, quint8(param));
    const lk::sim::SimParams &ram = drive().ramParams();
    switch (id) {
    case ControlParamId::AnglePid:
        QCOMPARE(v->pid(), ram.anglePid);
        break;
    case ControlParamId::SpeedPid:
        QCOMPARE(v->pid(), ram.speedPid);
        break;
    case ControlParamId::CurrentPid:
        QCOMPARE(v->pid(), ram.currentPid);
        break;
    case ControlParamId::InputTorqueLimit:
        QCOMPARE(v->value(), qint32(ram.maxTorque));
        break;
    case ControlParamId::InputSpeedLimit:
        QCOMPARE(v->value(), ram.maxSpeedRaw);
        break;
    case ControlParamId::InputAngleLimit:
        QCOMPARE(qint64(v->value()), ram.maxAngleRaw);
        break;
    case ControlParamId::InputCurrentRamp:
        QCOMPARE(v->value(), ram.currentRamp);
        break;
    case ControlParamId::InputSpeedRamp:
        QCOMPARE(v->value(), ram.speedRampDps2);
        break;
    }
}

void tst_SimCanControl::writeChangesRamOnly()
{
    const lk::sim::SimParams rom = drive().rom().params;
    const auto echo =
        ask(proto::build::writeControlParamPid(kV236, ControlParamId::SpeedPid, 77, 33, 5));
    QVERIFY(echo);
    QCOMPARE(echo->pid(), (std::array<quint16, 3>{77, 33, 5})); // the value after writing
    QCOMPARE(drive().ramParams().speedPid, (std::array<quint16, 3>{77, 33, 5}));
    const auto ramp =
        ask(proto::build::writeControlParam(kV236, ControlParamId::InputCurrentRamp, 70000));
    QVERIFY(ramp);
    QCOMPARE(ramp->value(), 70000); // int32 on CAN, beyond RS485's int16
    QCOMPARE(drive().ramParams().currentRamp, 70000);
    // Read back through 0xC0: RAM holds it.
    QCOMPARE(ask(proto::build::readControlParam(kV236, ControlParamId::SpeedPid))->pid(),
             (std::array<quint16, 3>{77, 33, 5}));
    // Nothing reached ROM; a power cycle brings the ROM values back.
    QCOMPARE(m_romWrites, 0);
    QVERIFY(drive().rom().params == rom);
    drive().restart();
    QCOMPARE(drive().ramParams().speedPid, rom.speedPid);
    QCOMPARE(ask(proto::build::readControlParam(kV236, ControlParamId::InputCurrentRamp))->value(),
             rom.currentRamp);
}

void tst_SimCanControl::physicsUsesTheWrittenGains()
{
    const double before = drive().physics().physicalGains().kpSpeed;
    QVERIFY(ask(proto::build::writeControlParamPid(kV236, ControlParamId::SpeedPid, 200, 40, 0)));
    const double after = drive().physics().physicalGains().kpSpeed;
    QVERIFY2(after > 2 * before, qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(after)));
    // The input speed ramp is the physics' acceleration limit (as V2.35's speed_ramp).
    QVERIFY(ask(proto::build::writeControlParam(kV236, ControlParamId::InputSpeedRamp, 1234)));
    QCOMPARE(drive().accelerationDps2(), 1234);
}

void tst_SimCanControl::refusedWriteAnswersTheValueKept()
{
    m_bus = std::make_unique<SimBus>();
    SimDriveModel v236 = SimDriveModel::forSeries(proto::Series::MF);
    v236.generation = Generation::V2_35;
    v236.quirks.paramWriteRefused = true;
    QVERIFY(m_bus->addDrive(kV236, v236));
    m_front = std::make_unique<SimCanFront>(*m_bus);
    const auto kept = drive().ramParams().anglePid;
    const auto echo =
        ask(proto::build::writeControlParamPid(kV236, ControlParamId::AnglePid, 1, 2, 3));
    QVERIFY(echo);
    QCOMPARE(echo->pid(), kept);
}

void tst_SimCanControl::silentWhereTheDialectHasNone()
{
    // The old CAN generation has no 0xC0: silent, counted as unanswered.
    const QByteArray old =
        proto::CanRecord::of(can::encodeControlParamRead(kOld, ControlParamId::AnglePid)).encode();
    QVERIFY(m_front->receive(old, 0.0).isEmpty());
    QCOMPARE(m_front->counters().unanswered, qint64(1));
    // An ID outside the table gets no answer.
    ControlParameter unknown;
    unknown.paramId = 0x99;
    const QList<SimReply> none = m_front->receive(
        proto::CanRecord::of(can::encodeControlParamWrite(kV236, unknown)).encode(), 0.0);
    QVERIFY2(none.isEmpty(), none.isEmpty() ? "" : none[0].bytes.toHex().constData());
    // On RS485 0xC0 is no command: a V2.35 drive there stays silent to it.
    SimBus rs485;
    SimDriveModel v235 = SimDriveModel::forSeries(proto::Series::MF);
    v235.generation = Generation::V2_35;
    QVERIFY(rs485.addDrive(3, v235));
    const QByteArray frame = proto::encodeFrame(0xC0, 3, QByteArray(7, '\0'));
    QVERIFY(rs485.receive(frame, 0.0).isEmpty());
}

QTEST_APPLESS_MAIN(tst_SimCanControl)
#include "tst_simcancontrol.moc"
