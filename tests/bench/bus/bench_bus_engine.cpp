// The engine's own ceiling: BusSession polling 3 drives of the in-process simulator
// (SimTransport) with no wire time and no reply delay, so that every microsecond counted is
// host work: queueing, encoding, the bus thread's event loop, parsing, matching, statistics
// and telemetry batching. Far above any real bus (1 Mbps carries ~1,500 transactions/s), so
// the engine is never the bottleneck.
//
// Prints one JSON line:
//   engine_txn_per_s     read_state2 polls completed per second
//   engine_txn_us        microseconds per transaction (1e6 / engine_txn_per_s)
//   engine_mix_txn_per_s the standard mix (9C, 9A, 92, 9D)
//   engine_traffic_txn_per_s   read_state2 polls per second with the traffic capture on (the
//                              bus thread records every request and reply, parsed frame and
//                              decode context included, and sends them in batches)
//   engine_traffic_events_per_txn traffic events delivered per poll meanwhile (2: a request
//                              and its reply; less where the capture drops events, past 4096
//                              per 50 ms delivery: this ceiling is far above that)

#include "BenchUtil.h"

#include <bus/BusSession.h>
#include <sim/SimBus.h>
#include <transport/SimTransport.h>

#include <QtCore/QCoreApplication>

using namespace lk;
using namespace lk::bus;

namespace {

constexpr double kWarmupS = 0.5;
constexpr double kMeasureS = 2.0;

TransportFactory simFactory()
{
    return [](int baud) -> std::unique_ptr<transport::Transport> {
        auto bus =
            sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("3:MF,17:MS,32:MG")));
        bus->setReplyDelay(0);
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        t->setBaud(baud);
        t->setWireTimeEmulation(false);
        return t;
    };
}

double measure(BusSession &session, const PollPlan &plan, double *trafficPerTxn = nullptr)
{
    quint64 events = 0;
    auto tc = QObject::connect(&session, &BusSession::trafficCaptured,
                               [&events](const TrafficBatch &b) { events += b.size(); });
    std::vector<double> times;
    auto c = QObject::connect(&session, &BusSession::telemetryReceived,
                              [&times](const TelemetryBatch &b) {
                                  for (const TelemetrySample &s : b)
                                      times.push_back(s.time);
                              });
    session.startPolling(plan);
    bench::spin(int((kWarmupS + kMeasureS) * 1000) + 300);
    session.stopPolling();
    bench::spin(100);
    QObject::disconnect(c);
    QObject::disconnect(tc);
    if (trafficPerTxn)
        *trafficPerTxn = times.empty() ? 0 : double(events) / double(times.size());
    if (times.size() < 2)
        return 0;
    const double t0 = times.front() + kWarmupS;
    const double t1 = t0 + kMeasureS;
    const auto n =
        std::count_if(times.begin(), times.end(), [t0, t1](double t) { return t >= t0 && t < t1; });
    return double(n) / kMeasureS;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    BusSession session;
    session.open(simFactory(), 115200);
    if (!bench::waitUntil([&] { return session.connection().isOpen(); }, 10000))
        return 1;
    session.setSeries(3, protocol::Series::MF);
    session.setSeries(17, protocol::Series::MS);
    session.setSeries(32, protocol::Series::MG);
    PollPlan state2 = PollPlan::standard({3, 17, 32});
    state2.commands = {protocol::Command::ReadState2};
    const double rate = measure(session, state2);
    const double mix = measure(session, PollPlan::standard({3, 17, 32}));
    session.setTrafficCapture(true);
    double trafficEvents = 0;
    const double traffic = measure(session, state2, &trafficEvents);
    session.close();
    bench::JsonLine json;
    json.add(QStringLiteral("engine_txn_per_s"), rate, 0);
    json.add(QStringLiteral("engine_txn_us"), rate > 0 ? 1e6 / rate : 0, 2);
    json.add(QStringLiteral("engine_mix_txn_per_s"), mix, 0);
    json.add(QStringLiteral("engine_traffic_txn_per_s"), traffic, 0);
    json.add(QStringLiteral("engine_traffic_events_per_txn"), trafficEvents, 2);
    json.print();
    return 0;
}
