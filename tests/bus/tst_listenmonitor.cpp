// A listen-only BusWorker decodes another master's traffic: both directions arrive on one
// stream (delivered here straight from the FakeTransport, on a clock the test advances). The
// drives' replies become the same telemetry samples a poll gives, drives appear from what they
// answer (generation and series learnt from the replies), the master's commanded values become
// samples of their own, and ListenStatistics counts what that master did. Nothing is written.

#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/ListenStatistics.h>
#include <protocol/Reply.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {

/// A listening worker and a script of what another master and its drives say.
struct Tap {
    Tap()
        : rig(std::make_unique<WorkerRig>(WorkerRig::Setup{}, relaxedConfig(), 1000000,
                                          RigTime::Manual, LinkMode::ListenOnly))
    {
        drives.add(1, Series::MF);
        drives.add(2, Series::MS);
        drives.add(3, Series::MS);
        QObject::connect(rig->worker.get(), &BusWorker::telemetryReceived, rig->worker.get(),
                         [this](const TelemetryBatch &b) { samples += b; });
    }
    /// The bytes arrive now, as one chunk from the adapter.
    void hear(const QByteArray &bytes) { emit rig->transport->bytesReceived(bytes); }
    /// A request and the table drive's answer to it, `gapMs` apart.
    void transaction(const protocol::Request &request, double gapMs = 0.2)
    {
        const protocol::Frame frame = request.toFrame();
        hear(frame.encode());
        rig->timers->advance(gapMs);
        const QByteArray reply = drives.reply(frame);
        if (!reply.isEmpty())
            hear(reply);
        rig->timers->advance(0.3);
    }
    /// Let the batcher deliver.
    void settle() { rig->timers->advance(100); }
    QVector<TelemetrySample> of(int id) const
    {
        QVector<TelemetrySample> out;
        for (const TelemetrySample &s : samples)
            out += s.id == id ? QVector<TelemetrySample>{s} : QVector<TelemetrySample>{};
        return out;
    }

    FakeDrives drives;
    std::unique_ptr<WorkerRig> rig;
    TelemetryBatch samples;
};

protocol::Request read(Command c, int id)
{
    return plainRequest(c, id);
}

protocol::Request speed(int id, double dps)
{
    protocol::Request r = plainRequest(Command::Speed, id);
    r.payload = protocol::SpeedCommand{qint32(std::lround(dps * 100))};
    return r;
}

} // namespace

class tst_ListenMonitor : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void observedRepliesAreTheSamplesAPollGives();
    void commandedValuesBesideTheReplies();
    void positionCommands_data();
    void positionCommands();
    void drivesAppearFromWhatTheyAnswer();
    void statisticsOfTheOtherMaster();
};

void tst_ListenMonitor::observedRepliesAreTheSamplesAPollGives()
{
    Tap tap;
    tap.transaction(read(Command::ReadState2, 1));
    tap.transaction(read(Command::ReadMultiTurn, 1));
    tap.settle();
    const QVector<TelemetrySample> got = tap.of(1);
    QCOMPARE(got.size(), 2);
    // What the same reply gives an active session's poll (TelemetrySample::fromReply).
    const protocol::Frame state2 = read(Command::ReadState2, 1).toFrame();
    protocol::StreamParser parser;
    protocol::Frame replyFrame;
    parser.feed(tap.drives.reply(state2),
                [&](const protocol::ParseEvent &ev) { replyFrame = ev.frame; });
    const protocol::ReplyDecodeResult dec = protocol::decodeReply(replyFrame, {});
    QVERIFY(dec.reply.has_value());
    const std::optional<TelemetrySample> polled = TelemetrySample::fromReply(*dec.reply, 0);
    QVERIFY(polled.has_value());
    QCOMPARE(got.at(0).fields, polled->fields);
    QCOMPARE(got.at(0).speedDps, polled->speedDps);
    QCOMPARE(got.at(0).iqA, polled->iqA);
    QCOMPARE(got.at(0).encoder, polled->encoder);
    QCOMPARE(got.at(0).source, Command::ReadState2);
    QCOMPARE(got.at(0).cycle, quint64(0)); // answers no poll of ours
    QVERIFY(got.at(1).has(TelemetryField::MultiTurn));
    QCOMPARE(got.at(1).multiTurnDeg, -123.45);
    QCOMPARE(tap.rig->log->writtenCopy().size(), 0);
}

void tst_ListenMonitor::commandedValuesBesideTheReplies()
{
    Tap tap;
    tap.transaction(speed(1, 123.45));
    protocol::Request to = plainRequest(Command::MultiPosition, 1);
    to.payload = protocol::MultiPositionCommand{9000, std::nullopt};
    tap.transaction(to);
    protocol::Request torque = plainRequest(Command::Torque, 1);
    torque.payload = protocol::TorqueCommand{-500};
    tap.transaction(torque); // V2.3 (no model seen): the command's scale is 32/2000 A
    tap.settle();
    const QVector<TelemetrySample> got = tap.of(1);
    // Each command, then the drive's reply to it (state2: actual speed, iq, encoder).
    QCOMPARE(got.size(), 6);
    QCOMPARE(got.at(0).fields, TelemetryFields(TelemetryField::CommandedSpeed));
    QCOMPARE(got.at(0).commandedSpeedDps, 123.45);
    QCOMPARE(got.at(0).source, Command::Speed);
    QVERIFY(got.at(1).has(TelemetryField::Speed));
    QCOMPARE(got.at(2).fields, TelemetryFields(TelemetryField::CommandedAngle));
    QCOMPARE(got.at(2).commandedAngleDeg, 90.0);
    QCOMPARE(got.at(4).fields, TelemetryFields(TelemetryField::CommandedIq));
    QCOMPARE(got.at(4).commandedIqA, -500 * 32.0 / 2000.0);
    QVERIFY(!TelemetrySample::commandedFields().testFlag(TelemetryField::Speed));
}

namespace {
/// The request of a position command row: the payload its command takes.
protocol::Request positionRequest(Command command, int angleRaw, int direction, int maxSpeedRaw)
{
    protocol::Request r = plainRequest(command, 1);
    const std::optional<quint32> limit =
        maxSpeedRaw < 0 ? std::nullopt : std::optional<quint32>(quint32(maxSpeedRaw));
    switch (command) {
    case Command::MultiPosition:
    case Command::MultiPositionLimited:
        r.payload = protocol::MultiPositionCommand{angleRaw, limit};
        break;
    case Command::SinglePosition:
    case Command::SinglePositionLimited:
        r.payload = protocol::SinglePositionCommand{protocol::SpinDirection(direction),
                                                    quint32(angleRaw), limit};
        break;
    default:
        r.payload = protocol::IncrementPositionCommand{angleRaw, limit};
        break;
    }
    return r;
}
} // namespace

void tst_ListenMonitor::positionCommands_data()
{
    QTest::addColumn<int>("command");
    QTest::addColumn<int>("angleRaw");    // 0.01 deg
    QTest::addColumn<int>("direction");   // 0 clockwise, 1 counter-clockwise (0xA5/0xA6)
    QTest::addColumn<int>("maxSpeedRaw"); // 0.01 dps; -1: the command has none
    QTest::addColumn<int>("fields");      // TelemetryFields the sample carries
    const auto bits = [](TelemetryFields f) { return int(f.toInt()); };
    using F = TelemetryField;
    QTest::newRow("0xA4 multi-turn, limited")
        << 0xA4 << -36000 << 0 << 12345 << bits(F::CommandedAngle | F::CommandedMaxSpeed);
    QTest::newRow("0xA5 single-turn, counter-clockwise")
        << 0xA5 << 27050 << 1 << -1 << bits(F::CommandedSingleTurn | F::CommandedDirection);
    QTest::newRow("0xA6 single-turn, clockwise, limited")
        << 0xA6 << 35999 << 0 << 36000
        << bits(F::CommandedSingleTurn | F::CommandedDirection | F::CommandedMaxSpeed);
    QTest::newRow("0xA7 increment, negative")
        << 0xA7 << -9050 << 0 << -1 << bits(F::CommandedIncrement);
    QTest::newRow("0xA8 increment, limited")
        << 0xA8 << 18000 << 0 << 50000 << bits(F::CommandedIncrement | F::CommandedMaxSpeed);
}

void tst_ListenMonitor::positionCommands()
{
    // What a position command asks is its own column: a single-turn target is no multi-turn
    // angle, and an increment is no target at all (the listener does not know where the
    // drive starts from).
    QFETCH(int, command);
    QFETCH(int, angleRaw);
    QFETCH(int, direction);
    QFETCH(int, maxSpeedRaw);
    QFETCH(int, fields);
    Tap tap;
    tap.transaction(positionRequest(Command(command), angleRaw, direction, maxSpeedRaw));
    tap.settle();
    const QVector<TelemetrySample> got = tap.of(1);
    QCOMPARE(got.size(), 2); // the command, then the drive's state2 reply
    const TelemetrySample &c = got.at(0);
    QCOMPARE(int(c.fields.toInt()), fields);
    QCOMPARE(int(c.source), command);
    QVERIFY(TelemetrySample::commandedFields().testFlags(c.fields));
    const double angleDeg = angleRaw / 100.0;
    if (c.has(TelemetryField::CommandedAngle))
        QCOMPARE(c.commandedAngleDeg, angleDeg);
    if (c.has(TelemetryField::CommandedSingleTurn))
        QCOMPARE(c.commandedSingleTurnDeg, angleDeg);
    if (c.has(TelemetryField::CommandedIncrement))
        QCOMPARE(c.commandedIncrementDeg, angleDeg);
    if (c.has(TelemetryField::CommandedDirection))
        QCOMPARE(c.commandedDirection, direction);
    if (c.has(TelemetryField::CommandedMaxSpeed))
        QCOMPARE(c.commandedMaxSpeedDps, maxSpeedRaw / 100.0);
    QVERIFY(got.at(1).has(TelemetryField::Speed));
    QCOMPARE(tap.rig->log->writtenCopy().size(), 0);
}

void tst_ListenMonitor::drivesAppearFromWhatTheyAnswer()
{
    Tap tap;
    QSignalSpy known(tap.rig->worker.get(), &BusWorker::knownMotorsChanged);
    tap.transaction(read(Command::ReadState2, 9)); // nobody answers ID 9
    QVERIFY(!tap.rig->worker->knownMotors().contains(9));
    tap.transaction(read(Command::ReadState2, 3)); // an MS drive, series not known yet
    QVERIFY(tap.rig->worker->knownMotors().contains(3));
    QCOMPARE(tap.rig->worker->knownMotors().value(3).series, std::nullopt);
    tap.transaction(read(Command::ReadModel, 3)); // a model reply passes: MS, V2.3
    QCOMPARE(tap.rig->worker->knownMotors().value(3).series, std::optional(Series::MS));
    tap.transaction(read(Command::ReadState2, 3)); // now its power decodes as power
    // The user's series for a drive no model reply named stays.
    tap.rig->worker->setSeries(2, Series::MS);
    tap.transaction(read(Command::ReadState2, 2));
    QCOMPARE(tap.rig->worker->knownMotors().value(2).series, std::optional(Series::MS));
    // A brake reply (0x8C exists on V2.35 only) tells the generation of a drive without model.
    tap.hear(protocol::encodeFrame(0x8C, 4, QByteArray(1, char(protocol::kBrakeReadCode))));
    tap.hear(protocol::encodeFrame(0x8C, 4, QByteArray(1, '\x01')));
    QCOMPARE(tap.rig->worker->knownMotors().value(4).generation, protocol::Generation::V2_35);
    tap.settle();
    QVERIFY(!known.isEmpty());
    const QVector<TelemetrySample> ms = tap.of(3);
    QCOMPARE(ms.size(), 2);
    QVERIFY(ms.at(0).has(TelemetryField::IqA));   // before the model: read as iq (MF)
    QVERIFY(ms.at(1).has(TelemetryField::Power)); // after it: power
    QCOMPARE(ms.at(1).power, 500);
    QVERIFY(tap.of(2).at(0).has(TelemetryField::Power));
    QCOMPARE(tap.rig->log->writtenCopy().size(), 0);
}

void tst_ListenMonitor::statisticsOfTheOtherMaster()
{
    Tap tap;
    QSignalSpy stats(tap.rig->worker.get(), &BusWorker::listenStatisticsUpdated);
    for (int i = 0; i < 10; ++i) {
        tap.transaction(read(Command::ReadState2, 1), 1.0); // its replies come after ~1 ms
        tap.transaction(read(Command::ReadState1, 2), 0.5);
    }
    tap.transaction(read(Command::ReadState2, 7)); // no drive 7: unanswered
    tap.transaction(read(Command::ReadState2, 1));
    QByteArray spoilt = protocol::encodeFrame(0x9C, 1, {});
    spoilt[4] = char(spoilt.at(4) ^ 0x01); // bad header checksum
    tap.hear(spoilt);
    QVERIFY(tap.rig->runUntil([&] { return !stats.isEmpty(); }, 5000));
    const ListenStatistics s = stats.last().at(0).value<ListenStatistics>();
    QCOMPARE(s.requests, quint64(22));
    QCOMPARE(s.paired, quint64(21));
    QCOMPARE(s.unanswered, quint64(1));
    QCOMPARE(s.checksumErrors, quint64(1));
    QCOMPARE(s.baud, 1000000);
    QCOMPARE(s.perDrive.value(1).requests, quint64(11));
    QCOMPARE(s.perDrive.value(1).replies, quint64(11));
    QCOMPARE(s.perDrive.value(7).unanswered, quint64(1));
    QCOMPARE(s.perDrive.value(2).latency.samples, 10);
    QCOMPARE(s.perDrive.value(2).latency.medianMs, 0.5);
    QCOMPARE(s.perDrive.value(1).latency.maxMs, 1.0);
    QCOMPARE(s.perCommand.value(0x9C).requests, quint64(12));
    QCOMPARE(s.perCommand.value(0x9A).requests, quint64(10));
    QVERIFY(s.perCommand.value(0x9C).requestsPerSecond > 0);
    QVERIFY(s.busLoad > 0 && s.busLoad < 1);
    QVERIFY(s.bytes > 0);
    QCOMPARE(tap.rig->log->writtenCopy().size(), 0);
}

QTEST_GUILESS_MAIN(tst_ListenMonitor)
#include "tst_listenmonitor.moc"
