// What the traffic capture costs the bus thread per event: a request as written and a reply
// as parsed, each recorded with its parsed frame and the decode context of the moment (a
// registry lookup), against a bare event that only keeps the bytes, ID and command (what the
// view had before it stopped parsing on paint). The buffer is taken every 4096 events, as
// the 50 ms delivery would at ~80,000 events/s. Median of 7 runs of 200,000 events each.
//
// Prints one JSON line:
//   traffic_bare_ns    a bytes-only event (no frame, no context)
//   traffic_sent_ns    a request: frame taken from its own bytes, context looked up
//   traffic_frame_ns   a reply from the parser: frame shared, context looked up

#include "BenchUtil.h"

#include <bus/MotorRegistry.h>
#include <bus/TrafficRecorder.h>
#include <protocol/Reply.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QElapsedTimer>

using namespace lk;
using namespace lk::bus;

namespace {

constexpr int kEvents = 200000;
constexpr int kRuns = 7;

/// Nanoseconds per call of `record(recorder, i)`, taking the buffer as the worker does.
template <typename F> double nsPerEvent(F record)
{
    std::vector<double> runs;
    for (int r = 0; r < kRuns; ++r) {
        TrafficRecorder recorder;
        recorder.setEnabled(true);
        QElapsedTimer clock;
        clock.start();
        for (int i = 0; i < kEvents; ++i) {
            record(recorder, i);
            if ((i & (TrafficRecorder::kMaxPending - 1)) == TrafficRecorder::kMaxPending - 1)
                recorder.take(i);
        }
        runs.push_back(double(clock.nsecsElapsed()) / kEvents);
    }
    return bench::median(runs);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    MotorRegistry motors;
    motors.setSeries(3, protocol::Series::MF);
    motors.setSeries(17, protocol::Series::MS);
    motors.setSeries(32, protocol::Series::MG);
    const int ids[] = {3, 17, 32};

    const QByteArray request =
        protocol::build::plain(protocol::Command::ReadState2, 17).request->encode();
    protocol::State2 s;
    s.speedDps = 360;
    protocol::ParseEvent reply;
    reply.isFrame = true;
    reply.frame = protocol::Reply{protocol::Command::ReadState2, 17, s}.toFrame();
    reply.direction = protocol::FrameDirection::Reply;
    reply.bytes = reply.frame.encode();

    const double bare = nsPerEvent([&](TrafficRecorder &t, int i) {
        t.record(TrafficEvent::Kind::Frame, i, reply.bytes, reply.frame.id, reply.frame.command);
    });
    const double sent = nsPerEvent([&](TrafficRecorder &t, int i) {
        t.recordSent(i, request, motors.decodeContext(ids[i % 3]));
    });
    const double frame = nsPerEvent([&](TrafficRecorder &t, int i) {
        t.recordParseEvent(reply, i, motors.decodeContext(ids[i % 3]));
    });
    bench::JsonLine json;
    json.add(QStringLiteral("traffic_bare_ns"), bare, 1);
    json.add(QStringLiteral("traffic_sent_ns"), sent, 1);
    json.add(QStringLiteral("traffic_frame_ns"), frame, 1);
    json.print();
    return 0;
}
