// The bytes of the multi-motor torque frame (0x280) the engine sends: each drive's iq in its
// slot, 0 in the slots not named; nothing for what the frame cannot carry.

#include <bus/MultiTorque.h>
#include <protocol/CanRecord.h>
#include <protocol/RequestBuilder.h>

#include <QtTest/QtTest>

using namespace lk;
using protocol::Request;

Q_DECLARE_METATYPE(lk::protocol::Request)
Q_DECLARE_METATYPE(QVector<lk::protocol::Request>)

namespace {
Request torqueRaw(int id, qint16 raw)
{
    Request r;
    r.command = protocol::Command::Torque;
    r.id = static_cast<quint8>(id);
    protocol::TorqueCommand t;
    t.iqRaw = raw;
    r.payload = t;
    return r;
}
} // namespace

class tst_MultiTorqueEncoding : public QObject {
    Q_OBJECT
private slots:
    void frame_data();
    void frame();
    void documentedExampleFromAmps();
};

void tst_MultiTorqueEncoding::frame_data()
{
    QTest::addColumn<QVector<Request>>("torques");
    QTest::addColumn<QString>("candump"); ///< empty: nothing to send
    QTest::newRow("documented example")
        << QVector<Request>{torqueRaw(1, 100), torqueRaw(2, -100)} << "280#64009CFF00000000";
    QTest::newRow("any order") << QVector<Request>{torqueRaw(2, -100), torqueRaw(1, 100)}
                               << "280#64009CFF00000000";
    QTest::newRow("slot 4 alone") << QVector<Request>{torqueRaw(4, 2000)} << "280#000000000000D007";
    QTest::newRow("all four at the range's ends")
        << QVector<Request>{torqueRaw(1, -2000), torqueRaw(2, 2000), torqueRaw(3, 1),
                            torqueRaw(4, -1)}
        << "280#30F8D0070100FFFF";
    QTest::newRow("empty") << QVector<Request>{} << "";
    QTest::newRow("ID 5") << QVector<Request>{torqueRaw(5, 10)} << "";
    QTest::newRow("ID 0") << QVector<Request>{torqueRaw(0, 10)} << "";
    QTest::newRow("twice") << QVector<Request>{torqueRaw(1, 10), torqueRaw(1, 20)} << "";
    QTest::newRow("over 2000") << QVector<Request>{torqueRaw(1, 2001)} << "";
    QTest::newRow("not a torque") << QVector<Request>{*protocol::build::speed(1, 10).request} << "";
}

void tst_MultiTorqueEncoding::frame()
{
    QFETCH(QVector<Request>, torques);
    QFETCH(QString, candump);
    const QByteArray bytes = bus::encodeMultiTorque(torques);
    if (candump.isEmpty()) {
        QVERIFY(bytes.isEmpty());
        return;
    }
    QCOMPARE(bytes.size(), protocol::CanRecord::kSize);
    const std::optional<protocol::CanRecord> r = protocol::CanRecord::decode(bytes);
    QVERIFY(r);
    QCOMPARE(r->candumpText(), candump);
}

void tst_MultiTorqueEncoding::documentedExampleFromAmps()
{
    // The old CAN generation's scale is 32 A / 2000: 1.6 A is 100, as lkctl builds it.
    const protocol::DecodeContext oldCan{protocol::Series::MG, protocol::Generation::V2_3,
                                         protocol::Link::Can};
    const QVector<Request> torques{*protocol::build::torque(1, 1.6, oldCan).request,
                                   *protocol::build::torque(2, -1.6, oldCan).request};
    QCOMPARE(protocol::CanRecord::decode(bus::encodeMultiTorque(torques))->candumpText(),
             QStringLiteral("280#64009CFF00000000"));
}

QTEST_APPLESS_MAIN(tst_MultiTorqueEncoding)
#include "tst_multitorqueencoding.moc"
