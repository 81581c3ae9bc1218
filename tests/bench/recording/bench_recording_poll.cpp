// What recording costs the bus: the poll rate with the recorder on against the same bus with it
// off. lksim serves 3 drives on a pseudo-terminal at the baud with wire time and a 500 us
// turnaround (--busy-poll, as bench_bus_poll); the session talks to it through SerialTransport,
// bare or wrapped by recordingFactory into a SessionRecorder writing a file and the black box's
// ring (what lkstudio does with a recording running). The two are measured in turns, several
// times, so that a load that comes and goes on the machine falls on both alike.
//
// Prints one JSON line:
//   poll_txn_per_s_off_<baud>, poll_txn_per_s_on_<baud>   replies/s, read_state2, 3 drives
//   poll_ratio_recording_<baud>                           on / off (target >= 0.98)
//   poll_ratio_recording_median_pair_<baud>               the median of each turn's on / off
//   poll_ratio_recording_steady_<baud>                    median reply-to-reply gap off / on:
//                                                         what a stall of a loaded machine
//                                                         (which falls on one turn) leaves out
//   file_bytes_per_wire_byte_<baud>                       the recording's size on disk per
//                                                         byte that passed the wire
//   dropped_bytes_<baud>                                  what the recorder's queue lost
//
// Usage: bench_recording_poll [--seconds S] (per turn, default 2) [--turns N] (default 3)
#include "../bus/BenchUtil.h"
#include "LksimProcess.h"

#include <bus/BusClock.h>
#include <bus/BusSession.h>
#include <recording/BlackBox.h>
#include <recording/RecordingTransport.h>
#include <recording/SessionRecorder.h>
#include <transport/SerialTransport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QFileInfo>
#include <QtCore/QTemporaryDir>

#include <cstdio>

using namespace lk;

namespace {

/// Counts what passed the wire, for the file's size per wire byte.
class WireCounter : public recording::RecordSink {
public:
    void append(recording::RecordEvent event) override { m_bytes += event.bytes.size(); }
    qint64 bytes() const { return m_bytes.load(); }

private:
    std::atomic<qint64> m_bytes{0};
};

struct Turn {
    double txnPerS = 0;
    double gapMedianMs = 0; ///< between consecutive replies: the typical transaction
    qint64 fileBytes = 0;
    qint64 wireBytes = 0;
    quint64 dropped = 0;
};

/// Replies per second over `seconds` of read_state2 polling, after a warm-up, and the median
/// gap between consecutive replies (what a stall of the loaded machine does not move).
void pollRate(bus::BusSession &session, double seconds, Turn *turn)
{
    bus::PollPlan plan = bus::PollPlan::standard({3, 17, 32});
    plan.commands = {protocol::Command::ReadState2};
    std::vector<bus::BusStatistics> snapshots;
    std::vector<double> times;
    auto c =
        QObject::connect(&session, &bus::BusSession::statisticsUpdated,
                         [&snapshots](const bus::BusStatistics &s) { snapshots.push_back(s); });
    auto t = QObject::connect(&session, &bus::BusSession::telemetryReceived,
                              [&times](const bus::TelemetryBatch &b) {
                                  for (const bus::TelemetrySample &s : b)
                                      times.push_back(s.time);
                              });
    session.resetStatistics();
    session.startPolling(plan);
    bench::spin(500);
    const size_t from = snapshots.size();
    const size_t firstTime = times.size();
    bench::spin(int(seconds * 1000));
    session.stopPolling();
    QObject::disconnect(c);
    QObject::disconnect(t);
    std::vector<double> gaps;
    for (size_t i = firstTime + 1; i < times.size(); ++i)
        gaps.push_back((times[i] - times[i - 1]) * 1e3);
    turn->gapMedianMs = bench::median(gaps);
    if (snapshots.size() < from + 2)
        return;
    const bus::BusStatistics &a = snapshots[from];
    const bus::BusStatistics &b = snapshots.back();
    const quint64 good =
        (b.bus.replies - a.bus.replies) - (b.bus.unexpectedFrames - a.bus.unexpectedFrames);
    turn->txnPerS = b.time > a.time ? double(good) / (b.time - a.time) : 0;
}

bool runTurn(const QString &device, int baud, bool record, double seconds, const QString &dir,
             Turn *turn)
{
    transport::SerialSettings settings;
    settings.portName = device;
    bus::TransportFactory factory = transport::SerialTransport::factory(settings);
    auto recorder = std::make_shared<recording::SessionRecorder>();
    auto wire = std::make_shared<WireCounter>();
    const QString path = dir + QStringLiteral("/poll.lkrec");
    if (record) {
        recording::RecordingHeader header;
        header.toolVersion = QStringLiteral("bench");
        header.baud = baud;
        if (recorder->start(path, header)) {
            std::fprintf(stderr, "bench_recording_poll: cannot write %s\n", qPrintable(path));
            return false;
        }
        auto box = std::make_shared<recording::BlackBox>(header);
        auto fanout = std::make_shared<recording::RecordFanout>(
            std::vector<std::shared_ptr<recording::RecordSink>>{recorder, box, wire});
        factory = recording::recordingFactory(std::move(factory), std::move(fanout),
                                              bus::makeSteadyBusClock());
    }
    bus::BusConfig config;
    config.statisticsHz = 10;
    bus::BusSession session;
    session.open(std::move(factory), baud, config);
    if (!bench::waitUntil([&] { return session.connection().isOpen(); }, 10000)) {
        std::fprintf(stderr, "bench_recording_poll: cannot open %s\n", qPrintable(device));
        return false;
    }
    session.setSeries(3, protocol::Series::MF);
    session.setSeries(17, protocol::Series::MS);
    session.setSeries(32, protocol::Series::MG);
    pollRate(session, seconds, turn);
    session.close();
    bench::spin(100);
    if (record) {
        recorder->stop();
        turn->fileBytes = QFileInfo(path).size();
        turn->wireBytes = wire->bytes();
        turn->dropped = recorder->droppedBytes();
        QFile::remove(path);
    }
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    double seconds = 2;
    int turns = 3;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--seconds"))
            seconds = args[i + 1].toDouble();
        else if (args[i] == QLatin1String("--turns"))
            turns = args[i + 1].toInt();
    }
    QTemporaryDir dir;
    bench::JsonLine json;
    for (int baud : {1000000, 4000000}) {
        e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
        if (!sim.start({"--motors", "3:MF,17:MS,32:MG", "--wire-time", "--baud",
                        QString::number(baud), "--reply-delay-us", "500", "--busy-poll"})) {
            std::fprintf(stderr, "bench_recording_poll: %s\n", qPrintable(sim.errorString()));
            return 1;
        }
        double off = 0, on = 0;
        std::vector<double> gapOff, gapOn, pairRatios;
        qint64 file = 0, wire = 0;
        quint64 dropped = 0;
        for (int t = 0; t < turns; ++t) {
            Turn pair[2];
            for (const bool record : {false, true}) {
                Turn &turn = pair[record ? 1 : 0];
                if (!runTurn(sim.devicePath(), baud, record, seconds, dir.path(), &turn))
                    return 1;
                (record ? on : off) += turn.txnPerS / turns;
                (record ? gapOn : gapOff).push_back(turn.gapMedianMs);
                file += turn.fileBytes;
                wire += turn.wireBytes;
                dropped += turn.dropped;
            }
            if (pair[0].txnPerS > 0)
                pairRatios.push_back(pair[1].txnPerS / pair[0].txnPerS);
        }
        sim.stop();
        const QString suffix = QString::number(baud);
        json.add(QStringLiteral("poll_txn_per_s_off_") + suffix, off, 1);
        json.add(QStringLiteral("poll_txn_per_s_on_") + suffix, on, 1);
        json.add(QStringLiteral("poll_ratio_recording_") + suffix, off > 0 ? on / off : 0);
        json.add(QStringLiteral("poll_ratio_recording_median_pair_") + suffix,
                 bench::median(pairRatios));
        const double gapOnMs = bench::median(gapOn);
        json.add(QStringLiteral("poll_ratio_recording_steady_") + suffix,
                 gapOnMs > 0 ? bench::median(gapOff) / gapOnMs : 0);
        json.add(QStringLiteral("file_bytes_per_wire_byte_") + suffix,
                 wire > 0 ? double(file) / double(wire) : 0);
        json.addInt(QStringLiteral("dropped_bytes_") + suffix, qint64(dropped));
    }
    json.print();
    return 0;
}
