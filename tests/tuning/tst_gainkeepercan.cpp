// The CAN V2.36 control parameters through the engine (BusSession over the simulator's CAN
// front): typed 0xC0/0xC1 requests and replies, refused with the reason and nothing sent where
// the dialect has none, and GainKeeper reading, writing and restoring a V2.36 drive's gains in
// RAM with them (docs/CAN.md section 4.1).
#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimTransport.h>
#include <tuning/GainKeeper.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using protocol::Command;
using protocol::ControlParameter;
using protocol::ControlParamId;
using protocol::Generation;
using protocol::Series;
using tuning::GainKeeper;
using tuning::LoopGains;

namespace {

constexpr int kWaitMs = 60000; // a loaded machine; never a timing assertion
constexpr int kOld = 1;        // an old CAN MG
constexpr int kV236 = 2;       // a CAN V2.36 MF

TransportFactory factory(protocol::Link link)
{
    return [link](int rate) -> std::unique_ptr<transport::Transport> {
        auto bus = sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("1:MG,2:MF@2.35")));
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        t->setLink(link);
        t->setBaud(rate);
        return t;
    };
}

struct Rig {
    BusSession session;
    QSignalSpy completed{&session, &BusSession::requestCompleted};
    explicit Rig(protocol::Link link = protocol::Link::Can)
    {
        if (link == protocol::Link::Can) {
            session.setDriveIdentity({kOld, Series::MG, Generation::V2_3, {}});
            session.setDriveIdentity({kV236, Series::MF, Generation::V2_35, {}});
        }
        session.open(factory(link), 1000000);
        (void)QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs);
    }
    RequestResult request(const protocol::BuildResult &b)
    {
        if (!b.ok())
            return {};
        const quint64 t = session.send(*b.request);
        std::optional<RequestResult> out;
        (void)QTest::qWaitFor(
            [&] {
                for (const auto &args : completed) {
                    const auto res = args.at(0).value<RequestResult>();
                    if (res.ticket == t)
                        out = res;
                }
                return out.has_value();
            },
            kWaitMs);
        return out.value_or(RequestResult{});
    }
    std::optional<ControlParameter> read(ControlParamId p)
    {
        const RequestResult r = request(protocol::build::readControlParam(kV236, p));
        if (!r.ok() || !r.reply)
            return std::nullopt;
        return std::get<ControlParameter>(r.reply->payload);
    }
};

/// Runs one GainKeeper call to its end.
std::pair<bool, QString> wait(const std::function<void(GainKeeper::Done)> &call)
{
    std::optional<std::pair<bool, QString>> out;
    call([&](bool ok, const QString &why) { out = std::make_pair(ok, why); });
    (void)QTest::qWaitFor([&] { return out.has_value(); }, kWaitMs);
    return out.value_or(std::make_pair(false, QStringLiteral("no answer")));
}

} // namespace

class tst_GainKeeperCan : public QObject {
    Q_OBJECT
private slots:
    void readAndWriteThroughTheEngine();
    void refusedWhereTheDialectHasNone();
    void gainKeeperReadsWritesAndRestores();
};

void tst_GainKeeperCan::readAndWriteThroughTheEngine()
{
    Rig rig;
    const auto before = rig.read(ControlParamId::SpeedPid);
    QVERIFY(before);
    QCOMPARE(before->id(), std::optional<ControlParamId>(ControlParamId::SpeedPid));
    const RequestResult w = rig.request(
        protocol::build::writeControlParamPid(kV236, ControlParamId::SpeedPid, 61, 7, 2));
    QVERIFY2(w.ok(), qPrintable(w.reason));
    QCOMPARE(std::get<ControlParameter>(w.reply->payload).pid(),
             (std::array<quint16, 3>{61, 7, 2}));
    QCOMPARE(rig.read(ControlParamId::SpeedPid)->pid(), (std::array<quint16, 3>{61, 7, 2}));
    // A one-number parameter: typed value, written and read back.
    QVERIFY(rig.request(protocol::build::writeControlParam(kV236, ControlParamId::InputSpeedLimit,
                                                           123.45))
                .ok());
    QCOMPARE(rig.read(ControlParamId::InputSpeedLimit)->value(), 12345);
}

void tst_GainKeeperCan::refusedWhereTheDialectHasNone()
{
    // The old CAN generation: refused by name, nothing on the wire.
    Rig can;
    QSignalSpy traffic(&can.session, &BusSession::trafficCaptured);
    can.session.setTrafficCapture(true);
    const RequestResult old =
        can.request(protocol::build::readControlParam(kOld, ControlParamId::AnglePid));
    QVERIFY(!old.ok());
    QVERIFY2(old.reason.contains(QStringLiteral("read_control_param")), qPrintable(old.reason));
    QVERIFY2(old.reason.contains(QStringLiteral("nothing was sent")), qPrintable(old.reason));
    QTest::qWait(50);
    for (const auto &args : traffic)
        for (const TrafficEvent &e : args.at(0).value<TrafficBatch>())
            QVERIFY(e.command != quint8(Command::ReadControlParam));
    // RS485, a V2.35 drive that has answered read_model: refused before the codec.
    Rig rs485(protocol::Link::Rs485);
    QVERIFY(rs485.request(protocol::build::plain(Command::ReadModel, kV236)).ok());
    const RequestResult v235 = rs485.request(
        protocol::build::writeControlParam(kV236, ControlParamId::InputSpeedRamp, 100));
    QVERIFY(!v235.ok());
    QVERIFY2(v235.reason.contains(QStringLiteral("write_control_param")), qPrintable(v235.reason));
    // RS485, a drive never identified: the codec refuses it, nothing sent.
    const RequestResult unknown =
        rs485.request(protocol::build::readControlParam(5, ControlParamId::AnglePid));
    QCOMPARE(unknown.status, RequestStatus::Error);
    QVERIFY2(unknown.reason.contains(QStringLiteral("CAN V2.36 only")), qPrintable(unknown.reason));
}

void tst_GainKeeperCan::gainKeeperReadsWritesAndRestores()
{
    Rig rig;
    GainKeeper keeper(rig.session);
    auto r = wait([&](GainKeeper::Done d) { keeper.read(kV236, d); });
    QVERIFY2(r.first, qPrintable(r.second));
    QVERIFY(keeper.gains());
    const LoopGains read = *keeper.gains();
    QCOMPARE(read.link, protocol::Link::Can);
    QCOMPARE(read.generation, Generation::V2_35);
    const auto speed = rig.read(ControlParamId::SpeedPid)->pid();
    QCOMPARE(read.speed.kp, speed[0]);
    QCOMPARE(read.speed.ki, speed[1]);
    QCOMPARE(read.accelerationDps2, qint64(rig.read(ControlParamId::InputSpeedRamp)->value()));
    // Every request was a control parameter read.
    for (const auto &args : rig.completed) {
        const Command c = args.at(0).value<RequestResult>().request.command;
        QVERIFY(c == Command::ReadControlParam);
    }
    LoopGains changed = read;
    changed.speed.kp = quint16(read.speed.kp + 11);
    changed.accelerationDps2 = 4321;
    r = wait([&](GainKeeper::Done d) { keeper.write(changed, d); });
    QVERIFY2(r.first, qPrintable(r.second));
    QCOMPARE(rig.read(ControlParamId::SpeedPid)->pid()[0], changed.speed.kp);
    QCOMPARE(rig.read(ControlParamId::InputSpeedRamp)->value(), 4321);
    r = wait([&](GainKeeper::Done d) { keeper.restore(d); });
    QVERIFY2(r.first, qPrintable(r.second));
    QCOMPARE(rig.read(ControlParamId::SpeedPid)->pid(), speed);
    QCOMPARE(qint64(rig.read(ControlParamId::InputSpeedRamp)->value()), read.accelerationDps2);
    // Only RAM writes went out (0xC1); nothing else writes flash on CAN V2.36.
    for (const auto &args : rig.completed) {
        const Command c = args.at(0).value<RequestResult>().request.command;
        QVERIFY2(!protocol::CommandTable::info(c).writesFlash,
                 qPrintable(protocol::CommandTable::name(c)));
    }
}

QTEST_MAIN(tst_GainKeeperCan)
#include "tst_gainkeepercan.moc"
