// The recorder's figures (docs/RECORDING.md), in process. Prints one JSON line:
//   append_ns_per_chunk            SessionRecorder::append on the calling (bus) thread, writer
//                                  thread running; append_dropped_chunks: what its queue lost
//   transport_tx_overhead_ns       RecordingTransport::write minus a bare transport's write
//   transport_rx_overhead_ns       the same for a received chunk (record + re-emit)
//   blackbox_append_ns_per_chunk   BlackBox::append (encoding into the ring)
//   file_wire_ratio_poll           file bytes / wire bytes, 4 drives polled round robin
//                                  (0x9C, 0x9A, 0x92) at 115200 baud, one chunk per frame
//   file_wire_ratio_poll_split     the same with every reply arriving in two chunks (a USB
//                                  adapter's latency timer cutting it)
//   hour_*                         a synthesised recording of 4 drives at 1 Mbaud, full rate
//                                  (the bus limit of the mix), --minutes long (default 60):
//                                  its wire and file size, the time to write it, and the time
//                                  and peak RSS to open and decode it whole into per-drive
//                                  series (time, speed, torque) as "load all" would
//
// Usage: bench_recording [--minutes M] [--dir DIR] [--keep FILE] (the hour's recording is
// kept as FILE: bench_replay_gui opens it in lkstudio's window)
#include "../bus/BenchUtil.h"

#include <bus/BusClock.h>
#include <bus/BusTiming.h>
#include <bus/TelemetrySample.h>
#include <protocol/Reply.h>
#include <recording/BlackBox.h>
#include <recording/RecordFile.h>
#include <recording/RecordedFrameParser.h>
#include <recording/RecordingReader.h>
#include <recording/RecordingTransport.h>
#include <recording/SessionRecorder.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>

#include <sys/resource.h>

using namespace lk;
using namespace lk::recording;

namespace {

/// Moves nothing: the cost of the transport itself stays out of the figures.
class NullTransport : public transport::Transport {
public:
    bool open() override { return true; }
    void close() override {}
    void write(const QByteArray &bytes) override { m_written += bytes.size(); }
    State state() const override { return State::Open; }
    int baud() const override { return 1000000; }
    QString description() const override { return QStringLiteral("null"); }
    void receive(const QByteArray &bytes) { emit bytesReceived(bytes); }
    qint64 m_written = 0;
};

struct Poll {
    QByteArray request;
    QByteArray reply;
};

/// The replies of the poll mix for drive `id` (values vary a little per call).
QVector<Poll> pollMix(int id, int n)
{
    protocol::State2 s2;
    s2.temperatureC = 30;
    s2.torqueRaw = qint16(100 + n % 50);
    s2.speedDps = qint16(n % 720);
    s2.encoder = quint16(n * 37);
    protocol::State1 s1;
    s1.temperatureC = 30;
    s1.voltageRaw = 240;
    protocol::MultiTurnAngle m;
    m.raw = qint64(n) * 1234;
    return {{protocol::encodeFrame(0x9C, quint8(id), {}),
             protocol::Reply{protocol::Command::ReadState2, quint8(id), s2}.encode()},
            {protocol::encodeFrame(0x9A, quint8(id), {}),
             protocol::Reply{protocol::Command::ReadState1, quint8(id), s1}.encode()},
            {protocol::encodeFrame(0x92, quint8(id), {}),
             protocol::Reply{protocol::Command::ReadMultiTurn, quint8(id), m}.encode()}};
}

RecordingHeader header(int baud)
{
    RecordingHeader h;
    h.toolVersion = QStringLiteral("bench");
    h.linkDescription = QStringLiteral("synthesised @ %1").arg(baud);
    h.baud = baud;
    h.context = {{1, protocol::Series::MF, protocol::Generation::V2_3},
                 {2, protocol::Series::MS, protocol::Generation::V2_3},
                 {3, protocol::Series::MG, protocol::Generation::V2_35},
                 {4, protocol::Series::MF, protocol::Generation::V2_35}};
    return h;
}

/// Synthesise `seconds` of the poll mix on 4 drives at `baud`, at the bus limit: each
/// transaction takes the formula's time (wire time plus the 0.5 ms turnaround). Feeds
/// `sink(record)`; returns the wire bytes.
template <typename Sink> qint64 synthesise(double seconds, int baud, bool split, Sink sink)
{
    qint64 wire = 0;
    qint64 t = 0;
    const qint64 end = qint64(seconds * 1e9);
    for (int n = 0; t < end; ++n) {
        for (int id = 1; id <= 4 && t < end; ++id) {
            for (const Poll &p : pollMix(id, n)) {
                sink(RecordEvent::data(RecordEvent::Kind::Tx, t, p.request));
                const double txn = bus::BusTiming::transactionTimeS(int(p.request.size()),
                                                                    int(p.reply.size()), baud);
                const qint64 replyAt =
                    t + qint64((double(p.request.size() * 10) / baud + 0.0002) * 1e9);
                if (split) {
                    sink(RecordEvent::data(RecordEvent::Kind::Rx, replyAt, p.reply.left(6)));
                    sink(
                        RecordEvent::data(RecordEvent::Kind::Rx, replyAt + 60'000, p.reply.mid(6)));
                } else {
                    sink(RecordEvent::data(RecordEvent::Kind::Rx, replyAt, p.reply));
                }
                wire += p.request.size() + p.reply.size();
                t += qint64(txn * 1e9);
            }
        }
    }
    return wire;
}

/// Bytes of the file that holds `seconds` of the synthesised stream (64 KiB blocks, or one
/// per second, whichever comes first: the writer's rule).
double fileWireRatio(int baud, bool split)
{
    RecordEncoder enc;
    qint64 file = RecordEncoder::encodeHeader(header(baud)).size();
    qint64 blockStart = 0;
    const qint64 wire = synthesise(60, baud, split, [&](const RecordEvent &e) {
        if (!enc.isEmpty() && (enc.pendingBytes() >= 64 * 1024 || e.timeNs - blockStart >= 1e9))
            file += enc.takeBlock().size();
        if (enc.isEmpty())
            blockStart = e.timeNs;
        enc.append(e);
    });
    file += enc.takeBlock().size();
    return double(file) / double(wire);
}

double appendNs(const QString &dir, qint64 *dropped)
{
    SessionRecorder recorder;
    recorder.start(dir + QStringLiteral("/append.lkrec"), header(1000000));
    const QByteArray reply = pollMix(1, 1).first().reply;
    // Bursts of 10000 chunks (about 7 s of a saturated 1 Mbaud bus), the writer catching up
    // between them as it would on a real bus: only the appends are timed.
    constexpr int kBursts = 100;
    constexpr int kBurst = 10000;
    qint64 ns = 0;
    for (int b = 0; b < kBursts; ++b) {
        QElapsedTimer timer;
        timer.start();
        for (int i = 0; i < kBurst; ++i)
            recorder.append(
                RecordEvent::data(RecordEvent::Kind::Rx, (b * kBurst + i) * 700'000LL, reply));
        ns += timer.nsecsElapsed();
        QThread::msleep(30);
    }
    const double perChunk = double(ns) / (kBursts * kBurst);
    recorder.stop();
    *dropped = qint64(recorder.droppedBytes() / quint64(reply.size()));
    return perChunk;
}

double transportOverheadNs(const QString &dir, bool tx)
{
    constexpr int kN = 1'000'000;
    const QByteArray bytes = pollMix(1, 1).first().reply;
    qint64 received = 0;
    const auto run = [&](transport::Transport &t, NullTransport &inner) {
        QObject::connect(&t, &transport::Transport::bytesReceived,
                         [&received](const QByteArray &b) { received += b.size(); });
        QElapsedTimer timer;
        timer.start();
        for (int i = 0; i < kN; ++i) {
            if (tx)
                t.write(bytes);
            else
                inner.receive(bytes);
        }
        return double(timer.nsecsElapsed()) / kN;
    };
    NullTransport bare;
    const double plain = run(bare, bare);
    auto recorder = std::make_shared<SessionRecorder>();
    recorder->start(dir + QStringLiteral("/transport.lkrec"), header(1000000));
    auto *inner = new NullTransport;
    RecordingTransport recording(std::unique_ptr<transport::Transport>(inner), recorder,
                                 bus::makeSteadyBusClock());
    const double withRecording = run(recording, *inner);
    recorder->stop();
    return withRecording - plain;
}

double blackBoxNs()
{
    BlackBox box(header(1000000));
    const QByteArray reply = pollMix(1, 1).first().reply;
    constexpr int kN = 1'000'000;
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < kN; ++i)
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, i * 700'000LL, reply));
    return double(timer.nsecsElapsed()) / kN;
}

double peakRssMb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

/// Per drive, what "load all" keeps for a plot: time, speed and torque (iq or power).
struct Series {
    std::vector<double> time;
    std::vector<float> speed;
    std::vector<float> torque;
};

void hour(double minutes, const QString &dir, const QString &keep, bench::JsonLine &json)
{
    const QString path = dir + QStringLiteral("/hour.lkrec");
    QElapsedTimer timer;
    timer.start();
    RecordFile file;
    file.create(path);
    file.write(RecordEncoder::encodeHeader(header(1000000)));
    RecordEncoder enc;
    qint64 blockStart = 0;
    const qint64 wire = synthesise(minutes * 60, 1000000, false, [&](const RecordEvent &e) {
        if (!enc.isEmpty() && (enc.pendingBytes() >= 64 * 1024 || e.timeNs - blockStart >= 1e9))
            file.write(enc.takeBlock());
        if (enc.isEmpty())
            blockStart = e.timeNs;
        enc.append(e);
    });
    file.write(enc.takeBlock());
    file.close();
    const double writeS = timer.nsecsElapsed() * 1e-9;
    const double rssBefore = peakRssMb();

    timer.restart();
    std::map<int, Series> series;
    qint64 samples = 0;
    RecordingReader reader;
    reader.open(path);
    RecordedFrameParser parser(reader.header().context);
    const auto sink = [&](const RecordedFrame &f) {
        if (!f.event.isFrame || f.event.direction != protocol::FrameDirection::Reply)
            return;
        const auto reply = protocol::decodeReply(f.event.frame, f.context);
        if (!reply.reply)
            return;
        const auto s = bus::TelemetrySample::fromReply(*reply.reply, double(f.timeNs) * 1e-9);
        if (!s)
            return;
        ++samples;
        if (!s->has(bus::TelemetryField::Speed))
            return;
        Series &d = series[s->id];
        d.time.push_back(s->time);
        d.speed.push_back(float(s->speedDps));
        d.torque.push_back(float(s->has(bus::TelemetryField::Power) ? s->power : s->iqA));
    };
    RecordEvent e;
    while (reader.next(&e))
        parser.feed(e, sink);
    parser.finish(sink);
    const double decodeS = timer.nsecsElapsed() * 1e-9;

    json.add(QStringLiteral("hour_minutes"), minutes, 1);
    json.add(QStringLiteral("hour_wire_mb"), double(wire) / 1e6, 1);
    json.add(QStringLiteral("hour_file_mb"), double(QFileInfo(path).size()) / 1e6, 1);
    json.add(QStringLiteral("hour_write_s"), writeS, 2);
    json.addInt(QStringLiteral("hour_samples"), samples);
    json.add(QStringLiteral("hour_open_decode_s"), decodeS, 2);
    json.add(QStringLiteral("hour_peak_rss_mb_before_open"), rssBefore, 1);
    json.add(QStringLiteral("hour_peak_rss_mb"), peakRssMb(), 1);
    QFile::remove(keep);
    if (keep.isEmpty() || !QFile::rename(path, keep))
        QFile::remove(path);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    double minutes = 60;
    QString dirArg;
    QString keep;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--minutes"))
            minutes = args[i + 1].toDouble();
        else if (args[i] == QLatin1String("--dir"))
            dirArg = args[i + 1];
        else if (args[i] == QLatin1String("--keep"))
            keep = args[i + 1];
    }
    QTemporaryDir tmp(dirArg.isEmpty() ? QDir::tempPath() + QStringLiteral("/bench_recording")
                                       : dirArg + QStringLiteral("/bench_recording"));
    bench::JsonLine json;
    qint64 dropped = 0;
    json.add(QStringLiteral("append_ns_per_chunk"), appendNs(tmp.path(), &dropped), 1);
    json.addInt(QStringLiteral("append_dropped_chunks"), dropped);
    json.add(QStringLiteral("transport_tx_overhead_ns"), transportOverheadNs(tmp.path(), true), 1);
    json.add(QStringLiteral("transport_rx_overhead_ns"), transportOverheadNs(tmp.path(), false), 1);
    json.add(QStringLiteral("blackbox_append_ns_per_chunk"), blackBoxNs(), 1);
    json.add(QStringLiteral("file_wire_ratio_poll"), fileWireRatio(115200, false));
    json.add(QStringLiteral("file_wire_ratio_poll_split"), fileWireRatio(115200, true));
    hour(minutes, tmp.path(), keep, json);
    json.print();
    return 0;
}
