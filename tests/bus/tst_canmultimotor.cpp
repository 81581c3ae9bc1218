// The old CAN generation's multi-motor torque frame (0x280, docs/CAN.md section 5) on the
// simulator's CAN front: iq for drives 1..4 in one frame; each old drive in that mode answers
// on its own ID (0x140+ID) with the 0xA1 motion reply, in ascending ID order. V2.36 documents
// no such frame and a drive not in the mode ignores it: both stay silent.

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <sim/SimCanFront.h>
#include <sim/SimDrive.h>

#include <QtTest/QtTest>

namespace can = lk::protocol::can;
using lk::protocol::CanRecord;
using lk::protocol::Command;
using lk::sim::SimBus;
using lk::sim::SimCanFront;

namespace {

std::unique_ptr<SimBus> busOf(const char *spec)
{
    return SimBus::fromSpec(*lk::sim::SimBusSpec::parse(QString::fromLatin1(spec)));
}

/// The CAN IDs and B0 of the records `replies` carry, in order.
QStringList replyIds(const QList<lk::sim::SimReply> &replies)
{
    QStringList out;
    for (const lk::sim::SimReply &r : replies) {
        const auto record = CanRecord::decode(r.bytes);
        if (!record)
            return {QStringLiteral("not a record")};
        out << QStringLiteral("%1#%2")
                   .arg(record->canId, 3, 16, QLatin1Char('0'))
                   .arg(quint8(record->data.at(0)), 2, 16, QLatin1Char('0'));
    }
    return out;
}

QByteArray multiMotorFrame(const std::array<qint16, can::kMultiMotorDrives> &iq)
{
    const can::CanEncodeResult encoded = can::encodeMultiMotorTorque(iq);
    return CanRecord::of(*encoded.data).encode();
}

} // namespace

class tst_CanMultiMotor : public QObject {
    Q_OBJECT
private slots:
    void documentedExampleDecodes();
    void eachOldDriveAnswersOnItsOwnId_data();
    void eachOldDriveAnswersOnItsOwnId();
    void theDriveTakesItsIq();
};

void tst_CanMultiMotor::documentedExampleDecodes()
{
    // CAN.md section 9: `280#64009CFF00000000` is ID 1 +100, ID 2 -100.
    const auto iq = can::decodeMultiMotorTorque(
        can::CanData{can::kMultiMotorId, QByteArray::fromHex("64009CFF00000000")});
    QVERIFY(iq);
    QCOMPARE((*iq)[0], qint16(100));
    QCOMPARE((*iq)[1], qint16(-100));
    QCOMPARE(multiMotorFrame({100, -100, 0, 0}).size(), CanRecord::kSize);
}

void tst_CanMultiMotor::eachOldDriveAnswersOnItsOwnId_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<int>("notInMode"); ///< 0: every drive in the mode
    QTest::addColumn<QStringList>("replies");
    QTest::newRow("four old drives") << QStringLiteral("1:MG@can,2:MF@can,3:MG@can,4:MF@can") << 0
                                     << QStringList{"141#a1", "142#a1", "143#a1", "144#a1"};
    QTest::newRow("a V2.36 drive stays silent")
        << QStringLiteral("1:MG@can,2:MF@can236,4:MF@can") << 0 << QStringList{"141#a1", "144#a1"};
    QTest::newRow("a drive not in the mode stays silent")
        << QStringLiteral("1:MG@can,2:MF@can,3:MG@can") << 2 << QStringList{"141#a1", "143#a1"};
    QTest::newRow("ID 5 is not in the frame")
        << QStringLiteral("1:MG@can,5:MF@can") << 0 << QStringList{"141#a1"};
}

void tst_CanMultiMotor::eachOldDriveAnswersOnItsOwnId()
{
    QFETCH(QString, spec);
    QFETCH(int, notInMode);
    QFETCH(QStringList, replies);
    auto bus = busOf(qPrintable(spec));
    SimCanFront front(*bus);
    if (notInMode)
        front.setMultiMotorMode(notInMode, false);
    QCOMPARE(replyIds(front.receive(multiMotorFrame({10, -10, 20, -20}), 0.0)), replies);
}

void tst_CanMultiMotor::theDriveTakesItsIq()
{
    auto bus = busOf("1:MG@can,2:MF@can");
    SimCanFront front(*bus);
    front.receive(multiMotorFrame({200, -200, 0, 0}), 0.0);
    QCOMPARE(bus->drive(1)->activeCommand(), std::optional<Command>(Command::Torque));
    QCOMPARE(bus->drive(2)->activeCommand(), std::optional<Command>(Command::Torque));
    // Its iq comes from its own two bytes: the drives turn opposite ways.
    front.receive(QByteArray(), 0.5);
    QVERIFY2(
        bus->drive(1)->speedDps() > 0 && bus->drive(2)->speedDps() < 0,
        qPrintable(
            QStringLiteral("%1 %2").arg(bus->drive(1)->speedDps()).arg(bus->drive(2)->speedDps())));
}

QTEST_GUILESS_MAIN(tst_CanMultiMotor)
#include "tst_canmultimotor.moc"
