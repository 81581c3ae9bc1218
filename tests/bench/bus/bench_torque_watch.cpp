// The speed watch's overshoot: a free motor under torque on lksim (pseudo-terminal, wire-time
// emulation, 500 us turnaround), soft speed limit 720 dps, watched by the bus thread
// (bus::SpeedWatch) while the dashboard's plan polls it, as lkstudio does. Each trial sends
// the torque, waits for the watch's Motor Stop, and takes the highest speed the drive reported
// until it has coasted well below the limit (the motor only coasts after the stop, so the
// readings just after it carry the peak). Trials per case: kTrials; cases: MF4015 at 0.3 A
// and MH at 3.9 A, at 115200 and 1000000 baud.
//
// Prints one line per case, then one JSON line; per case C (mf_0.3a, mh_3.9a) and baud B:
//   watch_C_B_peak_dps_median, watch_C_B_peak_dps_max        highest speed read
//   watch_C_B_overshoot_dps_median, watch_C_B_overshoot_pct_median   peak - limit, and in %
//   watch_C_B_seen_dps_median                                the reading that tripped it
//   watch_C_B_reaction_ms_median, watch_C_B_reaction_ms_max  that reading to the stop's ack
//
// Run: build/tests/bench/bus/bench_torque_watch

#include "BenchSession.h"
#include "BenchUtil.h"
#include "LksimProcess.h"

#include <bus/BusSession.h>
#include <bus/PollPlan.h>
#include <bus/SpeedWatch.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QCoreApplication>

#include <cmath>
#include <cstdio>

using namespace lk;
using namespace lk::bus;

namespace {

constexpr int kTrials = 10;
constexpr double kLimitDps = 720;
constexpr int kId = 1;

struct Case {
    const char *key;
    const char *motor; ///< lksim --motors entry
    protocol::Series series;
    double amps;
};

const Case kCases[] = {
    {"mf_0.3a", "1:MF4015", protocol::Series::MF, 0.3},
    {"mh_3.9a", "1:MH", protocol::Series::MH, 3.9},
};

struct Figures {
    std::vector<double> peak, seen, reactionMs;
    bool ok = true;
};

double maxOf(const std::vector<double> &v)
{
    return v.empty() ? 0 : *std::max_element(v.cbegin(), v.cend());
}

/// One trial: torque, the watch's stop, the peak read until the drive is slow again.
bool trial(BusSession &session, const Case &c, Figures &f)
{
    std::optional<SpeedWatchTrip> trip;
    double peak = 0, last = 0;
    auto c1 = QObject::connect(&session, &BusSession::speedWatchTripped,
                               [&trip](const SpeedWatchTrip &t) { trip = t; });
    auto c2 = QObject::connect(&session, &BusSession::telemetryReceived,
                               [&](const TelemetryBatch &batch) {
                                   for (const TelemetrySample &s : batch) {
                                       if (s.id != kId || !s.has(TelemetryField::Speed))
                                           continue;
                                       peak = std::max(peak, std::abs(s.speedDps));
                                       last = std::abs(s.speedDps);
                                   }
                               });
    const auto built = protocol::build::torque(kId, c.amps, protocol::DecodeContext{c.series});
    session.send(*built.request);
    const bool tripped = bench::waitUntil([&] { return trip.has_value(); }, 20000);
    // Coasting: the peak is behind once the drive reads well below the limit.
    const bool slow = tripped && bench::waitUntil([&] { return last < kLimitDps / 2; }, 20000);
    const auto done = [&](bool ok) {
        QObject::disconnect(c1);
        QObject::disconnect(c2); // after the last wait: it follows `last`
        return ok;
    };
    if (!tripped || !slow || !trip->stopAcknowledged()) {
        std::fprintf(stderr, "bench_torque_watch: tripped %d, slow %d (last %.0f dps), stop %s\n",
                     int(tripped), int(slow), last,
                     tripped && trip->stopAcknowledged() ? "acknowledged" : "not acknowledged");
        return done(false);
    }
    f.peak.push_back(std::max(peak, std::abs(trip->speedDps)));
    f.seen.push_back(std::abs(trip->speedDps));
    f.reactionMs.push_back(trip->reactionMs());
    // Off before the next trial (the stop kept the torque command for Motor Run).
    session.send(*protocol::build::plain(protocol::Command::MotorOff, kId).request);
    if (!bench::waitUntil([&] { return last == 0; }, 20000)) {
        std::fprintf(stderr, "bench_torque_watch: still %.0f dps after Motor Off\n", last);
        return done(false);
    }
    return done(true);
}

Figures run(const Case &c, int baud)
{
    Figures f;
    e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
    if (!sim.start({"--motors", c.motor, "--wire-time", "--baud", QString::number(baud),
                    "--reply-delay-us", "500"})) {
        std::fprintf(stderr, "bench_torque_watch: %s\n", qPrintable(sim.errorString()));
        f.ok = false;
        return f;
    }
    BusSession session;
    if (!bench::openSerial(session, sim.devicePath(), baud)) {
        f.ok = false;
        return f;
    }
    session.setSeries(kId, c.series);
    safety::SoftLimits limits = safety::SoftLimits::defaults(c.series);
    limits.maxSpeedDps = kLimitDps;
    session.setSoftLimits(kId, limits);
    session.startPolling(PollPlan::standard({kId})); // the dashboard's plan, as fast as it goes
    bench::spin(300);
    for (int i = 0; i < kTrials && f.ok; ++i) {
        f.ok = trial(session, c, f);
        if (!f.ok)
            std::fprintf(stderr, "bench_torque_watch: %s at %d: trial %d failed\n", c.key, baud, i);
    }
    session.close();
    return f;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    bench::JsonLine json;
    json.addInt(QStringLiteral("watch_limit_dps"), qint64(kLimitDps));
    json.add(QStringLiteral("watch_threshold_dps"), SpeedWatch::thresholdDps(kLimitDps), 0);
    bool ok = true;
    for (const Case &c : kCases) {
        for (int baud : {115200, 1000000}) {
            const Figures f = run(c, baud);
            ok = ok && f.ok;
            const QString k = QStringLiteral("watch_%1_%2_").arg(QLatin1String(c.key)).arg(baud);
            const double peak = bench::median(f.peak);
            json.add(k + QStringLiteral("peak_dps_median"), peak, 0);
            json.add(k + QStringLiteral("peak_dps_max"), maxOf(f.peak), 0);
            json.add(k + QStringLiteral("overshoot_dps_median"), peak - kLimitDps, 0);
            json.add(k + QStringLiteral("overshoot_pct_median"), (peak / kLimitDps - 1) * 100, 1);
            json.add(k + QStringLiteral("seen_dps_median"), bench::median(f.seen), 0);
            json.add(k + QStringLiteral("reaction_ms_median"), bench::median(f.reactionMs), 2);
            json.add(k + QStringLiteral("reaction_ms_max"), maxOf(f.reactionMs), 2);
            std::printf("%s at %d baud, limit %.0f dps: peak %.0f dps (max %.0f), overshoot %.0f "
                        "dps (%.1f %%), tripped at %.0f dps, reaction %.2f ms (max %.2f), %zu "
                        "trials\n",
                        c.key, baud, kLimitDps, peak, maxOf(f.peak), peak - kLimitDps,
                        (peak / kLimitDps - 1) * 100, bench::median(f.seen),
                        bench::median(f.reactionMs), maxOf(f.reactionMs), f.peak.size());
        }
    }
    json.print();
    return ok ? 0 : 1;
}
