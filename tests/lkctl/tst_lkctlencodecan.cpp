// lkctl encode --link can|can236: a request frame in candump's notation with the layouts of the
// CAN generation chosen (docs/CAN.md). The expected frames are CAN.md's held vectors (section
// 7), not the output of the code under test; each printed frame is also read back by the
// core's CAN decoder as the command and values asked for.
#include "E2eUtil.h"
#include "protocol/CanLayout.h"
#include "protocol/Command.h"
#include "protocol/Request.h"

#include <QtTest/QtTest>

namespace {

using Result = lk::e2e::CtlResult;
using namespace lk::protocol;

Result encode(const QString &args)
{
    return lk::e2e::runProgram(QStringLiteral(LKCTL_PATH),
                               QStringList{QStringLiteral("encode")} +
                                   args.split(QLatin1Char(' '), Qt::SkipEmptyParts),
                               QProcessEnvironment::systemEnvironment(), 120000);
}

/// "141#A400680128230000" as the arbitration ID and B0..B7.
std::optional<can::CanData> parseCandump(const QByteArray &text)
{
    const QList<QByteArray> parts = text.trimmed().split('#');
    if (parts.size() != 2 || parts[1].size() != 16)
        return std::nullopt;
    bool ok = false;
    const quint32 id = parts[0].toUInt(&ok, 16);
    if (!ok)
        return std::nullopt;
    return can::CanData{id, QByteArray::fromHex(parts[1])};
}

} // namespace

class tst_LkctlEncodeCan : public QObject {
    Q_OBJECT
private slots:
    void heldVectors_data();
    void heldVectors();
    void refused_data();
    void refused();
    void helpNamesTheLinks();
};

void tst_LkctlEncodeCan::heldVectors_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<bool>("v236");
    QTest::addColumn<int>("command");
    const auto row = [](const char *name, const char *args, const char *frame, bool v236,
                        Command c) {
        QTest::newRow(name) << QString::fromLatin1(args) << QByteArray(frame) << v236 << int(c);
    };
    row("read state 2 (old)", "read_state2 --id 1 --link can", "141#9C00000000000000", false,
        Command::ReadState2);
    row("0xA4 90 deg at 360 dps (old)",
        "multi_position_limited --id 1 --angle-deg 90 --max-speed-dps 360 --link can",
        "141#A400680128230000", false, Command::MultiPositionLimited);
    // iq limit 512 on an MG: 512 x 66/4096 A = 8.25 A.
    row("V2.36 0xA2 iq limit 512, 100 dps",
        "speed --id 1 --speed-dps 100 --link can236 --series MG --torque-limit-a 8.25",
        "141#A200000210270000", true, Command::Speed);
    row("V2.36 0xC1 torque limit 2000",
        "write_control_param --id 1 --control-param input_torque_limit --max-torque 2000 "
        "--link can236",
        "141#C11E0000D0070000", true, Command::WriteControlParam);
    row("V2.36 0xC0 angle PID", "read_control_param --id 1 --control-param angle_pid --link can236",
        "141#C00A000000000000", true, Command::ReadControlParam);
    row("V2.36 0x8C read brake", "brake --id 1 --action read --link can236", "141#8C10000000000000",
        true, Command::Brake);
    row("motor off to drive 3 (V2.36)", "motor_off --id 3 --link can236", "143#8000000000000000",
        true, Command::MotorOff);
}

void tst_LkctlEncodeCan::heldVectors()
{
    QFETCH(QString, args);
    QFETCH(QByteArray, frame);
    QFETCH(bool, v236);
    QFETCH(int, command);
    const Result r = encode(args);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.out, frame + '\n');
    QVERIFY(r.err.isEmpty());
    // The core's CAN decoder reads it back as the command asked for, on drive's ID.
    const std::optional<can::CanData> data = parseCandump(r.out);
    QVERIFY(data);
    const std::optional<Frame> f = can::frameOf(*data);
    QVERIFY(f);
    DecodeContext context;
    context.link = Link::Can;
    context.generation = v236 ? Generation::V2_35 : Generation::V2_3;
    context.series = Series::MG;
    const RequestDecodeResult back = can::decodeRequest(*f, context);
    QVERIFY(back.request);
    QCOMPARE(int(back.request->command), command);
    QCOMPARE(int(back.request->id), data->canId - 0x140);
}

void tst_LkctlEncodeCan::refused_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QByteArray>("why");
    const auto row = [](const char *name, const char *args, const char *why) {
        QTest::newRow(name) << QString::fromLatin1(args) << QByteArray(why);
    };
    row("no model read on CAN", "read_model --id 1 --link can",
        "read_model does not exist on CAN (old)");
    row("0xC0 is not on the old generation",
        "read_control_param --id 1 --control-param angle_pid --link can",
        "read_control_param does not exist on CAN (old)");
    row("0xC0 is not on RS485", "read_control_param --id 1 --control-param angle_pid",
        "read_control_param exists on CAN V2.36 only");
    row("V2.36 torque without its scale", "torque --id 1 --iq-a 1 --link can236",
        "torque on CAN V2.36 needs --series");
    row("V2.36 speed without a torque limit", "speed --id 1 --speed-dps 10 --link can236",
        "speed on CAN V2.36 carries a torque limit, never 0");
    row("V2.36 speed with a limit under one iq unit",
        "speed --id 1 --speed-dps 10 --link can236 --series MF --torque-limit-a 0.001", "torque");
    row("a torque limit where no frame carries one",
        "speed --id 1 --speed-dps 10 --link can --torque-limit-a 2",
        "--torque-limit-a belongs to speed on --link can236 only");
    row("a torque limit on RS485", "speed --id 1 --speed-dps 10 --torque-limit-a 2",
        "--torque-limit-a belongs to speed on --link can236 only");
    row("an unknown link", "motor_off --id 1 --link usb", "--link must be rs485, can or can236");
    row("an unknown series", "torque --id 1 --iq-a 1 --link can --series XY",
        "--series must be MS, MF, MG or MH");
}

void tst_LkctlEncodeCan::refused()
{
    QFETCH(QString, args);
    QFETCH(QByteArray, why);
    const Result r = encode(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.out.isEmpty()); // nothing printed that a script could send
    QVERIFY2(r.err.startsWith("lkctl encode: ") && r.err.contains(why), r.err.constData());
}

void tst_LkctlEncodeCan::helpNamesTheLinks()
{
    const Result r = encode(QStringLiteral("--help"));
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("--link LINK       rs485 (default), can or can236"));
    // The CAN V2.36-only commands are listed, marked.
    QVERIFY2(r.out.contains("read_control_param (0xC0) can236"), r.out.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlEncodeCan)
#include "tst_lkctlencodecan.moc"
