// SimCanFront: the simulator's drives answering CAN records with their own physics, an old
// CAN drive (V2_3) and a V2.36 one (V2_35) on the same bus; what each generation keeps silent
// about; the reply ID; and what is not a request.

#include "SimTestUtil.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <protocol/LinkCodec.h>
#include <sim/SimCanFront.h>

#include <QtTest/QTest>

namespace proto = lk::protocol;
namespace can = lk::protocol::can;
using lk::sim::SimBus;
using lk::sim::SimCanFront;
using lk::sim::SimDriveModel;
using lk::sim::SimReply;
using lk::test::hex;
using proto::Command;
using proto::Generation;

namespace {

/// A record the host would write for `request` to a drive of `g`.
QByteArray hostRecord(const proto::Request &request, Generation g, proto::Series s)
{
    const proto::WireEncodeResult w =
        proto::encodeRequest(request, proto::DecodeContext{s, g, proto::Link::Can});
    if (!w.ok())
        qFatal("test request refused: %s", qPrintable(w.error.message()));
    return w.bytes;
}

QByteArray rawRecord(quint32 id, const char *data)
{
    return proto::CanRecord::of(can::CanData{id, hex(data)}).encode();
}

/// The one reply record of `out`, read back as the host reads it.
struct HostView {
    quint32 canId = 0;
    std::optional<proto::Reply> reply;
};
HostView readBack(const QList<SimReply> &out, Generation g, proto::Series s)
{
    HostView v;
    if (out.size() != 1)
        return v;
    v.canId = proto::CanRecord::decode(out[0].bytes)->canId;
    proto::CanRecordParser parser;
    parser.feed(out[0].bytes, [&](const proto::ParseEvent &e) {
        if (e.isFrame)
            v.reply =
                proto::decodeReply(e.frame, proto::DecodeContext{s, g, proto::Link::Can}).reply;
    });
    return v;
}

proto::Request plain(Command c, int id)
{
    return lk::test::req(proto::build::plain(c, id));
}

} // namespace

class tst_SimCanFront : public QObject {
    Q_OBJECT
private slots:
    void init();
    void bothGenerationsAnswerOnTheirIds();
    void v236SpeedWithTorqueLimitTurnsTheDrive();
    void whatCanDrivesDoNotAnswer_data();
    void whatCanDrivesDoNotAnswer();
    void oldClearAngleEchoesAndChangesNothing();
    void replyBaseCanBeChosen();
    void notRequests();
    void anotherNodesRepliesAreNotAnswered();
    void v236SetPositionTakesAnyAngle();
    void v236MotorOffClearsTheTurnCount();
    void zeroReplyCarriesTheOffsetOnBothGenerations();
    void v236SpeedTorqueLimitBoundsTheCurrent();

private:
    std::unique_ptr<SimBus> m_bus;
    std::unique_ptr<SimCanFront> m_front;
};

void tst_SimCanFront::init()
{
    m_bus = std::make_unique<SimBus>();
    SimDriveModel old = SimDriveModel::forSeries(proto::Series::MG);
    old.generation = Generation::V2_3;
    SimDriveModel v236 = SimDriveModel::forSeries(proto::Series::MF);
    v236.generation = Generation::V2_35;
    QVERIFY(m_bus->addDrive(1, old));
    QVERIFY(m_bus->addDrive(2, v236));
    m_front = std::make_unique<SimCanFront>(*m_bus);
}

void tst_SimCanFront::bothGenerationsAnswerOnTheirIds()
{
    const QList<SimReply> r1 = m_front->receive(rawRecord(0x141, "9C00000000000000"), 0.0);
    const HostView v1 = readBack(r1, Generation::V2_3, proto::Series::MG);
    QCOMPARE(v1.canId, 0x141u);
    QVERIFY(v1.reply);
    QCOMPARE(int(v1.reply->command), int(Command::ReadState2));
    QCOMPARE(std::get<proto::State2>(v1.reply->payload).encoder, m_bus->drive(1)->encoder());

    const QList<SimReply> r2 = m_front->receive(rawRecord(0x142, "9A00000000000000"), 0.01);
    const HostView v2 = readBack(r2, Generation::V2_35, proto::Series::MF);
    QCOMPARE(v2.canId, 0x182u); // the V2.36 document's reply ID
    QVERIFY(v2.reply);
    const auto s1 = std::get<proto::State1>(v2.reply->payload);
    QCOMPARE(s1.generation, Generation::V2_35);
    QVERIFY(qAbs(s1.voltageV() - m_bus->drive(2)->busVoltage()) < 0.01);
    QCOMPARE(r2[0].delaySeconds, m_bus->replyDelay());
    QCOMPARE(m_front->counters().requests, qint64(2));
    QCOMPARE(m_front->counters().replies, qint64(2));
}

void tst_SimCanFront::v236SpeedWithTorqueLimitTurnsTheDrive()
{
    const proto::DecodeContext ctx{proto::Series::MF, Generation::V2_35, proto::Link::Can};
    const proto::Request speed = lk::test::req(proto::build::speed(2, -360.0, ctx, 1.0));
    QVERIFY(
        !m_front->receive(hostRecord(speed, Generation::V2_35, proto::Series::MF), 0.0).isEmpty());
    m_bus->advanceTo(10.0);
    QVERIFY(m_bus->drive(2)->speedDps() < -180);
    // The multi-turn angle, negative now (ten turns back from within the first), crosses CAN
    // in seven bytes and comes back whole.
    const QList<SimReply> r = m_front->receive(
        hostRecord(plain(Command::ReadMultiTurn, 2), Generation::V2_35, proto::Series::MF), 10.0);
    const HostView v = readBack(r, Generation::V2_35, proto::Series::MF);
    QVERIFY(v.reply);
    const qint64 angle = std::get<proto::MultiTurnAngle>(v.reply->payload).raw;
    QVERIFY2(angle < 0, qPrintable(QString::number(angle)));
    QCOMPARE(angle, m_bus->drive(2)->multiTurnRaw());
}

void tst_SimCanFront::whatCanDrivesDoNotAnswer_data()
{
    QTest::addColumn<QByteArray>("record");
    QTest::newRow("0x12 to the old drive") << rawRecord(0x141, "1200000000000000");
    QTest::newRow("0x12 to the V2.36 drive") << rawRecord(0x142, "1200000000000000");
    QTest::newRow("0x93 to the V2.36 drive") << rawRecord(0x142, "9300000000000000");
    QTest::newRow("0x8C to the old drive") << rawRecord(0x141, "8C10000000000000");
    QTest::newRow("0x30 to the V2.36 drive") << rawRecord(0x142, "3000000000000000");
    QTest::newRow("an absent ID") << rawRecord(0x145, "9C00000000000000");
}

void tst_SimCanFront::whatCanDrivesDoNotAnswer()
{
    QFETCH(QByteArray, record);
    QVERIFY(m_front->receive(record, 0.0).isEmpty());
    QCOMPARE(m_front->counters().unanswered, qint64(1));
    QCOMPARE(m_front->counters().replies, qint64(0));
}

void tst_SimCanFront::oldClearAngleEchoesAndChangesNothing()
{
    const proto::DecodeContext ctx{proto::Series::MG, Generation::V2_3, proto::Link::Can};
    QVERIFY(!m_front
                 ->receive(hostRecord(lk::test::req(proto::build::speed(1, 360.0, ctx, 1.0)),
                                      Generation::V2_3, proto::Series::MG),
                           0.0)
                 .isEmpty());
    m_bus->advanceTo(1.0);
    const qint64 before = m_bus->drive(1)->multiTurnRaw();
    QVERIFY(before != 0);
    const QList<SimReply> r = m_front->receive(rawRecord(0x141, "9500000000000000"), 1.0);
    QCOMPARE(r.size(), 1);
    QCOMPARE(r[0].bytes, rawRecord(0x141, "9500000000000000"));
    QCOMPARE(m_bus->drive(1)->multiTurnRaw(), before);
}

void tst_SimCanFront::replyBaseCanBeChosen()
{
    m_front->setReplyBase(can::IdBase::Base140);
    QCOMPARE(readBack(m_front->receive(rawRecord(0x142, "9C00000000000000"), 0.0),
                      Generation::V2_35, proto::Series::MF)
                 .canId,
             0x142u);
    m_front->setReplyBase(can::IdBase::Base180);
    QCOMPARE(readBack(m_front->receive(rawRecord(0x141, "9C00000000000000"), 0.0), Generation::V2_3,
                      proto::Series::MG)
                 .canId,
             0x181u);
}

void tst_SimCanFront::notRequests()
{
    QByteArray bad = rawRecord(0x141, "9C00000000000000");
    bad[0] = 7; // no record of this version
    QVERIFY(m_front->receive(bad, 0.0).isEmpty());
    // A frame on an ID no drive owns (0x280 is the multi-motor frame: tst_canmultimotor).
    QVERIFY(m_front->receive(rawRecord(0x300, "64009CFF00000000"), 0.0).isEmpty());
    QVERIFY(m_front->receive(rawRecord(0x181, "9C326400F4010020"), 0.0).isEmpty()); // a reply
    QVERIFY(m_front->receive(rawRecord(0x141, "9C00"), 0.0).isEmpty());             // DLC 2
    QCOMPARE(m_front->counters().faults, qint64(2));
    QCOMPARE(m_front->counters().otherFrames, qint64(1));
    QCOMPARE(m_front->counters().requests, qint64(0));
    m_bus->faults().setSilenced(1, true);
    QVERIFY(m_front->receive(rawRecord(0x141, "9C00000000000000"), 0.0).isEmpty());
}

void tst_SimCanFront::anotherNodesRepliesAreNotAnswered()
{
    // The old generation replies on the request's own 0x140+ID: a listener, a second simulator
    // or a played drive puts such frames on the bus. Only requests are answered.
    const QList<SimReply> own = m_front->receive(rawRecord(0x141, "9C00000000000000"), 0.0);
    QCOMPARE(own.size(), 1);
    QCOMPARE(m_front->counters().requests, qint64(1));
    QVERIFY(m_front->receive(own[0].bytes, 0.0).isEmpty()); // its own reply, heard back
    QVERIFY(m_front->receive(rawRecord(0x141, "A2326400F4010020"), 0.0).isEmpty()); // 0xA2's
    // A read_state1 reply: temperature and voltage where the request has zeros.
    QVERIFY(m_front->receive(rawRecord(0x141, "9A1E00F000000000"), 0.0).isEmpty());
    QCOMPARE(m_front->counters().notRequests, qint64(3));
    QCOMPARE(m_front->counters().requests, qint64(1));
    QCOMPARE(m_front->counters().replies, qint64(1));
    // A request with its own layout still is one.
    QCOMPARE(m_front->receive(rawRecord(0x141, "A200000010270000"), 0.0).size(), 1);
}

// docs/CAN.md §4 and its vector: V2.36's 0x95 makes the current position read the angle it
// carries (RAM), and echoes; the old generation's echo changes nothing (above).
void tst_SimCanFront::v236SetPositionTakesAnyAngle()
{
    const QList<SimReply> r = m_front->receive(rawRecord(0x142, "95000000A08C0000"), 0.0);
    QCOMPARE(r.size(), 1);
    QCOMPARE(r[0].bytes, rawRecord(0x182, "95000000A08C0000"));
    QCOMPARE(m_bus->drive(2)->multiTurnRaw(), qint64(36000));
    QCOMPARE(m_front->receive(rawRecord(0x142, "950000006073FFFF"), 0.0).size(), 1); // -360.00
    QCOMPARE(m_bus->drive(2)->multiTurnRaw(), qint64(-36000));
    QCOMPARE(m_front->receive(rawRecord(0x142, "9500000000000000"), 0.0).size(), 1);
    QCOMPARE(m_bus->drive(2)->multiTurnRaw(), qint64(0));
    QCOMPARE(m_front->counters().requests, qint64(3));
}

// docs/CAN.md §4 and §6: V2.36 has no 0x93; its 0x80 also clears the turn count. The old
// generation's 0x80 leaves it.
void tst_SimCanFront::v236MotorOffClearsTheTurnCount()
{
    const proto::DecodeContext oldCtx{proto::Series::MG, Generation::V2_3, proto::Link::Can};
    const proto::DecodeContext newCtx{proto::Series::MF, Generation::V2_35, proto::Link::Can};
    QVERIFY(!m_front
                 ->receive(hostRecord(lk::test::req(proto::build::speed(1, 720.0, oldCtx, 1.0)),
                                      Generation::V2_3, proto::Series::MG),
                           0.0)
                 .isEmpty());
    QVERIFY(!m_front
                 ->receive(hostRecord(lk::test::req(proto::build::speed(2, 720.0, newCtx, 1.0)),
                                      Generation::V2_35, proto::Series::MF),
                           0.0)
                 .isEmpty());
    m_bus->advanceTo(3.0);
    const qint64 oldBefore = m_bus->drive(1)->multiTurnRaw();
    const qint64 newBefore = m_bus->drive(2)->multiTurnRaw();
    QVERIFY2(newBefore > 36000, qPrintable(QString::number(newBefore)));
    QCOMPARE(m_front->receive(rawRecord(0x141, "8000000000000000"), 3.0).size(), 1);
    QCOMPARE(m_front->receive(rawRecord(0x142, "8000000000000000"), 3.0).size(), 1);
    QCOMPARE(m_bus->drive(1)->multiTurnRaw(), oldBefore);
    const qint64 after = m_bus->drive(2)->multiTurnRaw();
    QVERIFY2(after >= 0 && after < 36000, qPrintable(QString::number(after)));
    QCOMPARE(after, newBefore % 36000); // the angle within the turn stays
}

// docs/CAN.md §3: on CAN the 0x19 reply carries the encoder offset that was set, on the old
// generation as on V2.36 (on RS485 V2.3 echoes).
void tst_SimCanFront::zeroReplyCarriesTheOffsetOnBothGenerations()
{
    const struct {
        int id;
        Generation generation;
        proto::Series series;
    } drives[] = {{1, Generation::V2_3, proto::Series::MG},
                  {2, Generation::V2_35, proto::Series::MF}};
    for (const auto &d : drives) {
        const HostView v =
            readBack(m_front->receive(rawRecord(0x140 + d.id, "1900000000000000"), 0.0),
                     d.generation, d.series);
        QVERIFY(v.reply);
        const auto zero = std::get<proto::ZeroWritten>(v.reply->payload);
        QVERIFY(zero.encoderOffset);
        QCOMPARE(*zero.encoderOffset, quint16(m_bus->drive(d.id)->rom().encoderZero));
        QVERIFY(*zero.encoderOffset != 0); // the drives' shafts sit away from the encoder's 0
    }
}

// docs/CAN.md §4: V2.36's 0xA2 carries a torque limit for that speed command; the speed loop's
// current stays within it.
void tst_SimCanFront::v236SpeedTorqueLimitBoundsTheCurrent()
{
    auto peakCurrent = [this](const char *data) {
        init();
        if (m_front->receive(rawRecord(0x142, data), 0.0).isEmpty())
            return -1.0;
        double peak = 0;
        for (int ms = 1; ms <= 200; ++ms) {
            m_bus->advanceTo(ms / 1000.0);
            peak = std::max(peak, std::abs(m_bus->drive(2)->iqA()));
        }
        return peak;
    };
    // 720 dps with a limit of 1 LSB, and with the largest the field takes (2048).
    const double limited = peakCurrent("A200010040190100");
    const double free = peakCurrent("A200000840190100");
    const double lsb = proto::iqCommandAmpsPerLsb(
        proto::DecodeContext{proto::Series::MF, Generation::V2_35, proto::Link::Can});
    QVERIFY2(limited > 0 && limited <= lsb * 1.05,
             qPrintable(QStringLiteral("%1 A, 1 LSB is %2 A").arg(limited).arg(lsb)));
    QVERIFY2(free > 20 * lsb, qPrintable(QStringLiteral("%1 A").arg(free)));
}

QTEST_APPLESS_MAIN(tst_SimCanFront)
#include "tst_simcanfront.moc"
