// What a listen-only session costs the bus thread on a saturated 4 Mbaud bus: another master
// polls four drives (MF, MG, MS, MH: read_state2, read_state1, read_multi_turn, read_state3,
// which the MS drive leaves unanswered) and sends one of them a speed command every round, back
// to back with no idle time. The synthesised byte stream (both directions, as a tap sees them)
// is handed over in chunks of what 1 ms of wire carries, each stamped at its place on the wire
// clock, to a ListenMonitor with the components of a real session: parser, pairing, registry
// learning, telemetry samples into the batcher (its timers fired as the wire clock passes, as
// the event loop would), statistics every 0.5 s; the traffic capture off (the plots hidden).
// The thread's CPU time for it, against the wire time it covers, is the share of a core.
// Median of 5 runs of 10 s of wire each.
//
// Prints one JSON line:
//   listen_core_pct        CPU time / wire time, % of one core (the issue asks <= 10 %)
//   wire_s, bytes          wire time and bytes per run
//   transactions_per_s     request/reply pairs the master made per second of wire
//   paired_ratio           replies paired / replies expected (answered requests)
//   samples                telemetry samples made per run

#include "../../support/ManualTimers.h"
#include "BenchUtil.h"

#include <bus/BusDiagnostics.h>
#include <bus/BusTiming.h>
#include <bus/ListenMonitor.h>
#include <bus/MotorRegistry.h>
#include <bus/TelemetryBatcher.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>

#include <ctime>

using namespace lk;
using namespace lk::bus;
using protocol::Command;

namespace {

constexpr int kBaud = 4000000;
constexpr double kWireS = 10;
constexpr int kRuns = 5;

double threadCpuS()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

QByteArray replyTo(Command command, int id, protocol::Series series, int round)
{
    protocol::Reply r;
    r.command = command;
    r.id = quint8(id);
    switch (command) {
    case Command::ReadState1:
        r.payload = protocol::State1{30, 240, 0};
        break;
    case Command::ReadState3:
        r.payload = protocol::State3{31, 64, -64, 0, protocol::kPhaseAmpsPerLsb};
        break;
    case Command::ReadMultiTurn:
        r.payload = protocol::MultiTurnAngle{qint64(round) * 36};
        break;
    default:
        r.payload =
            protocol::State2{32,
                             qint16(series == protocol::Series::MS ? 500 : 100 + round % 50),
                             series == protocol::Series::MS,
                             qint16(round % 360),
                             quint16(round & 0x3FFF),
                             protocol::kIqReplyAmpsPerLsb};
        break;
    }
    return r.encode();
}

/// One poll round of the master: every drive, every command, plus a speed command to drive 1.
/// `answered` counts the requests that got a reply.
QByteArray round(int n, int &answered)
{
    static const QVector<QPair<int, protocol::Series>> drives{{1, protocol::Series::MF},
                                                              {2, protocol::Series::MG},
                                                              {3, protocol::Series::MS},
                                                              {4, protocol::Series::MH}};
    static const QVector<Command> mix{Command::ReadState2, Command::ReadState1,
                                      Command::ReadMultiTurn, Command::ReadState3};
    QByteArray bytes;
    for (const auto &[id, series] : drives) {
        for (Command c : mix) {
            bytes += protocol::encodeFrame(quint8(c), quint8(id), {});
            if (series == protocol::Series::MS && c == Command::ReadState3)
                continue; // no phase currents on MS: silence, the master's timeout
            bytes += replyTo(c, id, series, n);
            ++answered;
        }
    }
    protocol::Request speed;
    speed.command = Command::Speed;
    speed.id = 1;
    speed.payload = protocol::SpeedCommand{qint32((n % 200) * 100)};
    bytes += speed.encode() + replyTo(Command::Speed, 1, protocol::Series::MF, n);
    ++answered;
    return bytes;
}

struct Run {
    double corePct = 0;
    qint64 bytes = 0;
    double transactionsPerS = 0;
    double pairedRatio = 0;
    qint64 samples = 0;
};

Run runOnce(const QByteArray &stream, int answered)
{
    auto clock = std::make_shared<testsupport::ManualClock>();
    testsupport::ManualTimers timers(clock);
    MotorRegistry motors;
    TelemetryBatcher telemetry(nullptr, timers.factory());
    qint64 samples = 0;
    QObject::connect(&telemetry, &TelemetryBatcher::batchReady,
                     [&samples](const TelemetryBatch &b) { samples += b.size(); });
    BusDiagnostics diagnostics(motors, clock, timers.factory());
    ListenMonitor monitor(motors, telemetry, diagnostics, clock);
    const qsizetype chunk = kBaud / BusTiming::kBitsPerByte / 1000; // 1 ms of wire
    const double chunkMs = 1.0;
    double sinceStatsMs = 0;
    const double cpu0 = threadCpuS();
    for (qsizetype at = 0; at < stream.size(); at += chunk) {
        monitor.feed(stream.mid(at, chunk), kBaud);
        timers.advance(chunkMs);
        if ((sinceStatsMs += chunkMs) >= 500) {
            sinceStatsMs = 0;
            monitor.snapshot(kBaud);
        }
    }
    telemetry.flush();
    const double cpu = threadCpuS() - cpu0;
    const double wireS = double(stream.size()) * BusTiming::kBitsPerByte / kBaud;
    Run r;
    r.corePct = 100 * cpu / wireS;
    r.bytes = stream.size();
    r.transactionsPerS = double(monitor.counts().paired) / wireS;
    r.pairedRatio = answered > 0 ? double(monitor.counts().paired) / answered : 0;
    r.samples = samples;
    return r;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const qint64 target = qint64(kWireS * kBaud / BusTiming::kBitsPerByte);
    QByteArray stream;
    stream.reserve(target + 4096);
    int answered = 0;
    for (int n = 0; stream.size() < target; ++n)
        stream += round(n, answered);
    std::vector<double> pct;
    Run last;
    for (int i = 0; i < kRuns; ++i) {
        last = runOnce(stream, answered);
        pct.push_back(last.corePct);
    }
    bench::JsonLine json;
    json.add(QStringLiteral("listen_core_pct"), bench::median(pct), 2);
    json.add(QStringLiteral("wire_s"), double(stream.size()) * BusTiming::kBitsPerByte / kBaud, 2);
    json.addInt(QStringLiteral("bytes"), last.bytes);
    json.add(QStringLiteral("transactions_per_s"), last.transactionsPerS, 0);
    json.add(QStringLiteral("paired_ratio"), last.pairedRatio, 4);
    json.addInt(QStringLiteral("samples"), last.samples);
    json.print();
    return 0;
}
