#include "FieldJsonTestUtil.h"
#include "protocol/FieldText.h"

#include <QtTest/QtTest>

using namespace lk::protocol;
using lk::fieldjsontest::req;
using lk::fieldjsontest::state2;

namespace {

State1 state1(qint8 t, quint16 voltageRaw, quint8 errors)
{
    State1 s;
    s.temperatureC = t;
    s.voltageRaw = voltageRaw;
    s.errorState = errors;
    return s;
}

} // namespace

class tst_FieldText : public QObject {
    Q_OBJECT
private slots:
    void request_data();
    void request();
    void reply_data();
    void reply();
    void frame_data();
    void frame();
};

void tst_FieldText::request_data()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<QString>("expected");
    QTest::newRow("speed") << req(build::speed(1, 100)) << "speed 100.00 dps";
    QTest::newRow("speed negative") << req(build::speed(1, -0.5)) << "speed -0.50 dps";
    QTest::newRow("torque") << req(build::torque(1, 1.5, {})) << "iq 1.50 A";
    QTest::newRow("open_loop") << req(build::openLoop(1, -500)) << "power -500";
    QTest::newRow("multi") << req(build::multiPosition(1, 720)) << "angle 720.00 deg";
    QTest::newRow("multi limited")
        << req(build::multiPosition(1, -90, 500)) << "angle -90.00 deg, max 500.00 dps";
    QTest::newRow("single") << req(build::singlePosition(1, SpinDirection::CounterClockwise, 90))
                            << "ccw to 90.00 deg";
    QTest::newRow("single limited")
        << req(build::singlePosition(1, SpinDirection::Clockwise, 0.5, 10))
        << "cw to 0.50 deg, max 10.00 dps";
    QTest::newRow("increment +") << req(build::incrementPosition(1, 45)) << "by +45.00 deg";
    QTest::newRow("increment -") << req(build::incrementPosition(1, -45, 360))
                                 << "by -45.00 deg, max 360.00 dps";
    QTest::newRow("pid") << req(build::writePid(1, 100, 90, 50, 40, 30, 20, false))
                         << "angle Kp 100 Ki 90, speed Kp 50 Ki 40, iq Kp 30 Ki 20";
    QTest::newRow("accel") << req(build::writeAcceleration(1, 1000)) << "accel 1000 dps/s";
    QTest::newRow("offset") << req(build::writeEncoderOffset(1, 1234)) << "offset 1234";
    QTest::newRow("motor_off") << req(build::plain(Command::MotorOff, 1)) << "";
    QTest::newRow("read_state2") << req(build::plain(Command::ReadState2, 1)) << "";
}

void tst_FieldText::request()
{
    QFETCH(Request, request);
    QFETCH(QString, expected);
    QCOMPARE(FieldText::request(request), expected);
}

void tst_FieldText::reply_data()
{
    QTest::addColumn<Reply>("reply");
    QTest::addColumn<QString>("expected");
    // 76 LSB = 76 * 33 / 2048 A = 1.2246 A
    QTest::newRow("state2 iq") << Reply{Command::ReadState2, 1, state2(31, 76, false, 360, 12345)}
                               << "T 31 C, iq 1.22 A, 360 dps, enc 12345";
    QTest::newRow("state2 power") << Reply{Command::Speed, 1, state2(-3, -500, true, -20, 0)}
                                  << "T -3 C, power -500, -20 dps, enc 0";
    QTest::newRow("state1 ok") << Reply{Command::ReadState1, 1, state1(40, 243, 0)}
                               << "T 40 C, 24.3 V";
    QTest::newRow("state1 flags") << Reply{Command::ClearErrors, 1, state1(90, 80, 0x0D)}
                                  << "T 90 C, 8.0 V, low voltage, over-temperature, "
                                     "error bits 0x04";
    QTest::newRow("state3") << Reply{Command::ReadState3, 1,
                                     State3{30, 64, -32, -1, lk::protocol::kPhaseAmpsPerLsb}}
                            << "T 30 C, ia 1.00 A, ib -0.50 A, ic -0.02 A";
    QTest::newRow("encoder") << Reply{Command::ReadEncoder, 1, EncoderReading{100, 200, 300}}
                             << "enc 100, raw 200, offset 300";
    QTest::newRow("multi turn") << Reply{Command::ReadMultiTurn, 1, MultiTurnAngle{-3600050}}
                                << "angle -36000.50 deg";
    QTest::newRow("single turn") << Reply{Command::ReadSingleTurn, 1, SingleTurnAngle{35999}}
                                 << "angle 359.99 deg";
    QTest::newRow("zero echo") << Reply{Command::WriteZeroRom, 1, ZeroWritten{}} << "";
    QTest::newRow("zero data") << Reply{Command::WriteZeroRom, 1, ZeroWritten{77}} << "offset 77";
    QTest::newRow("ack") << Reply{Command::MotorStop, 1, Acknowledged{}} << "";
    QTest::newRow("accel") << Reply{Command::ReadAccel, 1, Acceleration{500}} << "accel 500 dps/s";
    ModelInfo m;
    m.driverName = QStringLiteral("LKDRV01");
    m.motorName = QStringLiteral("MG4010E-i10");
    m.hardwareRaw = 10;
    m.firmwareRaw = 21;
    QTest::newRow("model V2.3") << Reply{Command::ReadModel, 1, m}
                                << "LKDRV01 / MG4010E-i10, hw 1.0, fw 2.1";
    m.generation = Generation::V2_35;
    m.hardwareRaw = 300;
    m.firmwareRaw = 235;
    QTest::newRow("model V2.35") << Reply{Command::ReadModel, 1, m}
                                 << "LKDRV01 / MG4010E-i10, hw 3.00, fw 2.35";
}

void tst_FieldText::reply()
{
    QFETCH(Reply, reply);
    QFETCH(QString, expected);
    QCOMPARE(FieldText::reply(reply), expected);
}

void tst_FieldText::frame_data()
{
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<quint8>("command");
    QTest::addColumn<int>("direction");
    QTest::addColumn<bool>("ms");
    QTest::addColumn<QString>("expected");
    const QByteArray state2 = QByteArray::fromHex("1FF40168010030");
    QTest::newRow("reply MF") << state2 << quint8(0x9C) << int(FrameDirection::Reply) << false
                              << "T 31 C, iq 8.06 A, 360 dps, enc 12288";
    QTest::newRow("reply MS") << state2 << quint8(0x9C) << int(FrameDirection::Reply) << true
                              << "T 31 C, power 500, 360 dps, enc 12288";
    QTest::newRow("request") << QByteArray::fromHex("10270000") << quint8(0xA2)
                             << int(FrameDirection::Request) << false << "speed 100.00 dps";
    QTest::newRow("echo") << QByteArray::fromHex("409C") << quint8(0x91)
                          << int(FrameDirection::Echo) << false << "offset 40000";
    QTest::newRow("wrong direction is empty")
        << state2 << quint8(0x9C) << int(FrameDirection::Request) << false << "";
}

void tst_FieldText::frame()
{
    QFETCH(QByteArray, data);
    QFETCH(quint8, command);
    QFETCH(int, direction);
    QFETCH(bool, ms);
    QFETCH(QString, expected);
    DecodeContext ctx;
    ctx.series = ms ? Series::MS : Series::MF;
    QCOMPARE(FieldText::frame(Frame{command, 1, data}, FrameDirection(direction), ctx), expected);
}

QTEST_APPLESS_MAIN(tst_FieldText)
#include "tst_fieldtext.moc"
