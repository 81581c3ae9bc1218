// Simulator figures for the tuning assistant (issue #13), printed as one JSON line:
//   physics_us_per_sim_s_4drives   CPU time to simulate one second of 4 drives in closed loop
//                                  (speed, position and two torque/off drives), 0.2 ms substeps;
//                                  the GUI's built-in simulated bus runs 4 drives in real time
//   realtime_factor_4drives        simulated seconds per CPU second for those 4 drives
//   poll_spacing_median_ms_<baud>  median gap between read_state2 replies of one drive polled
//                                  back to back through SimTransport with wire-time emulation
//   poll_spacing_p90_ms_<baud>     90th percentile of those gaps
//   poll_rate_hz_<baud>            replies per second achieved
//   wire_limit_ms_<baud>           what the wire allows: 0x9C request + reply at 8N1 plus the
//                                  simulated drive's turnaround (SimBus::kDefaultReplyDelay)

#include "../bus/BenchUtil.h"

#include <bus/BusTiming.h>
#include <motor/SeriesLimits.h>
#include <protocol/RequestBuilder.h>
#include <sim/DrivePhysics.h>
#include <sim/SimBus.h>
#include <transport/SimTransport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>

#include <memory>

using namespace lk;

namespace {

constexpr double kSimulatedSeconds = 20.0;
constexpr double kPollSeconds = 2.0;

sim::DrivePhysics makePhysics(protocol::Series s, sim::LoopMode mode)
{
    const motor::SeriesLimits &l = motor::seriesLimits(s);
    sim::DrivePhysics p(sim::RotorParams::forSeries(s), l.maxCurrentA, l.maxSpeedDps());
    p.setSupplyVoltage(l.nominalSupplyV);
    p.setGains({100, 100, 50, 40, 50, 50});
    p.setAccelerationDps2(20000);
    sim::LoopTarget t;
    t.mode = mode;
    t.maxSpeedDps = l.maxSpeedDps();
    t.speedDps = 500;
    t.positionDeg = 1.0e6; // a long move: the position loop works all the time
    t.currentA = 0.5;
    p.setTarget(t);
    return p;
}

/// CPU microseconds per simulated second of four drives, advanced in 10 ms slices as the
/// simulated bus does between requests.
double physicsCostUs()
{
    std::vector<sim::DrivePhysics> drives{
        makePhysics(protocol::Series::MF, sim::LoopMode::Speed),
        makePhysics(protocol::Series::MS, sim::LoopMode::Position),
        makePhysics(protocol::Series::MG, sim::LoopMode::Position),
        makePhysics(protocol::Series::MH, sim::LoopMode::Torque)};
    QElapsedTimer clock;
    clock.start();
    for (double t = 0; t < kSimulatedSeconds; t += 0.01) {
        for (sim::DrivePhysics &d : drives)
            d.advance(0.01);
    }
    const double us = clock.nsecsElapsed() / 1e3;
    double sink = 0;
    for (const sim::DrivePhysics &d : drives)
        sink += d.positionDeg();
    if (!std::isfinite(sink))
        std::fprintf(stderr, "bench_sim_loops: physics diverged\n");
    return us / kSimulatedSeconds;
}

void pollSpacing(int baud, bench::JsonLine &json)
{
    auto bus = std::make_unique<sim::SimBus>();
    bus->addDrive(1, sim::SimDriveModel::forSeries(protocol::Series::MF));
    transport::SimTransport link(std::move(bus));
    link.setBaud(baud);
    link.setWireTimeEmulation(true);
    link.open();
    const QByteArray request =
        protocol::build::plain(protocol::Command::ReadState2, 1).request->encode();
    std::vector<double> replies;
    QElapsedTimer clock;
    QObject::connect(&link, &transport::Transport::bytesReceived, [&](const QByteArray &) {
        replies.push_back(clock.nsecsElapsed() / 1e6);
        if (clock.elapsed() < kPollSeconds * 1000)
            link.write(request); // the next poll as soon as the reply is in: half duplex
    });
    clock.start();
    link.write(request);
    bench::waitUntil([&] { return clock.elapsed() > kPollSeconds * 1000 + 100; },
                     int(kPollSeconds * 1000) + 1000);
    link.close();
    std::vector<double> gaps;
    for (size_t i = 1; i < replies.size(); ++i)
        gaps.push_back(replies[i] - replies[i - 1]);
    const QString suffix = QString::number(baud);
    json.add(QStringLiteral("poll_spacing_median_ms_") + suffix, bench::median(gaps), 3);
    std::sort(gaps.begin(), gaps.end());
    json.add(QStringLiteral("poll_spacing_p90_ms_") + suffix,
             gaps.empty() ? 0 : gaps[gaps.size() * 9 / 10], 3);
    json.add(QStringLiteral("poll_rate_hz_") + suffix, replies.size() / kPollSeconds, 0);
    json.add(QStringLiteral("wire_limit_ms_") + suffix,
             bus::BusTiming::transactionTimeS(protocol::Command::ReadState2, baud,
                                              sim::SimBus::kDefaultReplyDelay) *
                 1e3,
             3);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    bench::JsonLine json;
    const double us = physicsCostUs();
    json.add(QStringLiteral("physics_us_per_sim_s_4drives"), us, 0);
    json.add(QStringLiteral("realtime_factor_4drives"), 1e6 / us, 1);
    for (int baud : {115200, 1000000})
        pollSpacing(baud, json);
    json.print();
    return 0;
}
