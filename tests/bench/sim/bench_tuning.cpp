// Frequency response and gain search figures (issue #25), on lksim over its pseudo-terminal
// at 1 Mbaud with wire-time emulation, one drive of each series on each generation:
//   freq_*: the measured Bode of the speed loop against the simulator's own transfer function
//           (SpeedLoopTransfer), on an MF and an MG of each generation and an MF with a
//           resonance and encoder counts: the largest dB and degree errors up to a quarter of
//           the sample rate reached, that rate, and the points compared;
//   freqpos_*: the measured Bode of the position loop (a sine of the angle around where the
//           drive is, inside an angle window) against PositionLoopTransfer, on a frictionless
//           MF (V2.3) and MG (V2.35) (friction=0: Coulomb friction is the one part of a sine
//           around a standstill that is not linear); `bench_tuning position` runs only these;
//   tune_*: a full speed-loop gain search: its time, and the gains read (the defaults) beside
//           the suggested ones with their rise time, overshoot and settling time;
//   tunepos_*: the same for the position loop's search (the angle gains, steps of 10 deg from
//           where the drive is inside a wide angle window); `bench_tuning position` runs these
//           after the position Bode.
// Every candidate and a side-by-side table of default vs suggested gains go to standard error.
#include "../bus/BenchSession.h"
#include "../bus/BenchUtil.h"

#include <E2eUtil.h>
#include <LksimProcess.h>
#include <protocol/RequestBuilder.h>
#include <sim/PositionLoopTransfer.h>
#include <sim/SpeedLoopTransfer.h>
#include <tuning/FrequencySweepRunner.h>
#include <tuning/GainSearchRunner.h>

#include <QtCore/QCoreApplication>

#include <cmath>
#include <cstdio>
#include <string_view>

using namespace lk;
using namespace lk::tuning;
using protocol::Series;

namespace {

constexpr int kBaud = 1000000;

struct Drive {
    int id;
    Series series;
    bool v235;
    const char *plant = ""; ///< PlantOptions in the bus spec
};
/// One drive of each series on each generation, and an MF with a resonance at 80 Hz and a
/// 14-bit encoder behind its speed estimate.
const Drive kDrives[] = {{1, Series::MS, false},
                         {2, Series::MF, false},
                         {3, Series::MG, false},
                         {4, Series::MH, false},
                         {5, Series::MS, true},
                         {6, Series::MF, true},
                         {7, Series::MG, true},
                         {8, Series::MH, true},
                         {9, Series::MF, false, "resonance=80/0.1+counts=16384"}};
/// The position loop's drives: not tuned.
const Drive kPositionDrives[] = {{10, Series::MF, false, "friction=0"},
                                 {11, Series::MG, true, "friction=0"}};

QString key(const Drive &d)
{
    return protocol::seriesName(d.series) +
           (d.v235 ? QStringLiteral("_v235") : QStringLiteral("_v23")) +
           (std::string_view(d.plant) == "friction=0" ? QStringLiteral("_frictionless")
            : *d.plant                                ? QStringLiteral("_resonant")
                                                      : QString());
}

template <typename Runner, typename Result, typename Spec>
std::optional<Result> run(bus::BusSession &session, const Spec &spec, int id,
                          std::optional<safety::SoftLimits> limits = std::nullopt)
{
    Runner runner(session);
    std::optional<Result> result;
    QObject::connect(&runner, &Runner::finished, [&](const Result &r) { result = r; });
    QObject::connect(&runner, &Runner::failed, [&](const Result &r) { result = r; });
    runner.start(spec, limits.value_or(safety::SoftLimits::defaults(session.series(id))));
    if (!bench::waitUntil([&] { return result.has_value(); }, 300000))
        runner.abort();
    bench::waitUntil([&] { return result.has_value(); }, 30000);
    return result;
}

/// The simulated drive's own speed (or position) loop for the gains read from it.
template <typename Transfer> Transfer transferFor(const Drive &d, const LoopGains &g)
{
    const auto u8 = [](quint16 v) { return quint8(std::min<int>(v, 255)); };
    return Transfer::forSeries(d.series,
                               {u8(g.angle.kp), u8(g.angle.ki), u8(g.speed.kp), u8(g.speed.ki),
                                u8(g.current.kp), u8(g.current.ki)},
                               {g.angle.kd, g.speed.kd, g.current.kd},
                               sim::PlantOptions::parse(d.plant)->resonance);
}

bool bode(bus::BusSession &session, const Drive &d, bench::JsonLine &json)
{
    FrequencySweepSpec spec;
    spec.id = d.id;
    spec.fromHz = 2;
    spec.toHz = 400;
    spec.points = 14;
    spec.amplitude = 60;
    spec.operatingPoint = 300;
    std::optional<safety::SoftLimits> limits;
    if (std::string_view(d.plant) == "friction=0") { // the position loop's drives
        spec.loop = SweepLoop::Position;
        spec.operatingPoint.reset(); // where the drive is
        spec.fromHz = 1;
        spec.toHz = 100;
        spec.points = 12;
        spec.amplitude = 2; // deg: 2 pi x 100 Hz x 2 deg = 1257 dps, under both top speeds
        limits = safety::SoftLimits::defaults(d.series);
        limits->minAngleDeg = -1e6;
        limits->maxAngleDeg = 1e6;
    }
    const auto r = run<FrequencySweepRunner, FrequencySweepResult>(session, spec, d.id, limits);
    if (!r || !r->ok() || !r->gains) {
        std::fprintf(stderr, "bench_tuning: the sweep of drive %d failed: %s\n", d.id,
                     r ? qPrintable(r->message) : "no result");
        return false;
    }
    const bool position = spec.loop == SweepLoop::Position;
    const auto speedLoop = transferFor<sim::SpeedLoopTransfer>(d, *r->gains);
    const auto positionLoop = transferFor<sim::PositionLoopTransfer>(d, *r->gains);
    const auto simDb = [&](double hz) {
        return position ? positionLoop.magnitudeDb(hz) : speedLoop.magnitudeDb(hz);
    };
    const auto simDeg = [&](double hz) {
        return position ? positionLoop.phaseDeg(hz) : speedLoop.phaseDeg(hz);
    };
    double maxDb = 0, maxDeg = 0;
    std::fprintf(stderr, "Bode of drive %d's %s loop (%s), %.0f samples/s:\n", d.id,
                 position ? "position" : "speed", qPrintable(key(d)), r->response.sampleRateHz);
    for (const FrequencyPoint &p : r->response.points) {
        const double db = p.magnitudeDb - simDb(p.hz);
        const double deg = std::remainder(p.phaseDeg - simDeg(p.hz), 360.0);
        maxDb = std::max(maxDb, std::abs(db));
        maxDeg = std::max(maxDeg, std::abs(deg));
        std::fprintf(stderr, "  %7.2f Hz  %7.2f dB %7.1f deg  sim %7.2f dB %7.1f deg  q %.3f\n",
                     p.hz, p.magnitudeDb, p.phaseDeg, simDb(p.hz), simDeg(p.hz), p.quality);
    }
    const QString k = (position ? QStringLiteral("freqpos_") : QStringLiteral("freq_")) + key(d) +
                      QLatin1Char('_');
    json.add(k + "sample_rate_hz", r->response.sampleRateHz, 1);
    json.add(k + "resolved_hz", r->response.resolvedHz(), 1);
    json.addInt(k + "points", r->response.points.size());
    json.add(k + "max_db_error", maxDb, 2);
    json.add(k + "max_deg_error", maxDeg, 1);
    if (const auto bw = r->response.figures().bandwidthHz)
        json.add(k + "bandwidth_hz", *bw, 1);
    return true;
}

/// One drive's search, for the side-by-side table.
struct TuneRow {
    Drive drive;
    StepLoop loop = StepLoop::Speed;
    double seconds = 0;
    int candidates = 0;
    std::optional<CandidateScore> defaults, suggested;
};

double ms(const Metric &m)
{
    return m.value.value_or(std::nan("")) * 1e3;
}

bool tune(bus::BusSession &session, const Drive &d, StepLoop loop, bench::JsonLine &json,
          QVector<TuneRow> &rows)
{
    GainSearchSpec spec;
    spec.id = d.id;
    std::optional<safety::SoftLimits> limits;
    if (loop == StepLoop::Position) {
        spec = GainSearchSpec::forPosition(d.id);
        limits = safety::SoftLimits::defaults(d.series);
        limits->minAngleDeg = -1e6;
        limits->maxAngleDeg = 1e6;
    }
    const auto r = run<GainSearchRunner, GainSearchResult>(session, spec, d.id, limits);
    if (!r || !r->ok()) {
        std::fprintf(stderr, "bench_tuning: the search on drive %d failed: %s\n", d.id,
                     r ? qPrintable(r->message) : "no result");
        return false;
    }
    const QString k =
        (loop == StepLoop::Position ? QStringLiteral("tunepos_") : QStringLiteral("tune_")) +
        key(d) + QLatin1Char('_');
    json.add(k + "seconds", r->seconds, 1);
    json.addInt(k + "candidates", r->candidates.size());
    const auto put = [&](const QString &which, const CandidateScore &c) {
        json.addInt(k + which + "_kp", GainSearchStrategy::tuned(c.gains, loop).kp);
        json.addInt(k + which + "_ki", GainSearchStrategy::tuned(c.gains, loop).ki);
        json.add(k + which + "_rise_ms", ms(c.metrics.riseTimeS), 2);
        json.add(k + which + "_overshoot_pct", c.metrics.overshootPct.value.value_or(-1), 1);
        json.add(k + which + "_settling_ms", ms(c.metrics.settling5S), 1);
    };
    TuneRow row{d, loop, r->seconds, int(r->candidates.size()), {}, {}};
    if (r->baseline) {
        row.defaults = r->candidates[*r->baseline];
        put(QStringLiteral("default"), *row.defaults);
    }
    if (r->best) {
        row.suggested = r->candidates[*r->best];
        put(QStringLiteral("suggested"), *row.suggested);
    }
    for (const CandidateScore &c : r->candidates)
        std::fprintf(stderr, "  drive %d %s Kp %3d Ki %3d  rise %6.2f ms  overshoot %5.1f %%  %s\n",
                     d.id, loop == StepLoop::Position ? "angle" : "speed",
                     GainSearchStrategy::tuned(c.gains, loop).kp,
                     GainSearchStrategy::tuned(c.gains, loop).ki, ms(c.metrics.riseTimeS),
                     c.metrics.overshootPct.value.value_or(-1), c.accepted() ? "accepted" : "-");
    rows.append(row);
    return true;
}

/// Default vs suggested gains of the loop searched per drive: Kp/Ki, rise (10-90 %), overshoot,
/// settling (5 %).
void printTable(const QVector<TuneRow> &rows)
{
    std::fprintf(stderr, "\n%-9s %-5s %6s %5s | %-8s %8s %7s %8s | %-8s %8s %7s %8s | %s\n",
                 "drive", "loop", "tune s", "cands", "default", "rise ms", "over %", "settl ms",
                 "suggest", "rise ms", "over %", "settl ms", "faster");
    const auto cell = [](const std::optional<CandidateScore> &c, StepLoop loop) {
        if (!c)
            return QStringLiteral("%1 %2 %3 %4").arg("-", -8).arg("-", 8).arg("-", 7).arg("-", 8);
        const PidTriple &g = GainSearchStrategy::tuned(c->gains, loop);
        return QStringLiteral("%1 %2 %3 %4")
            .arg(QStringLiteral("%1/%2").arg(g.kp).arg(g.ki), -8)
            .arg(ms(c->metrics.riseTimeS), 8, 'f', 2)
            .arg(c->metrics.overshootPct.value.value_or(std::nan("")), 7, 'f', 1)
            .arg(ms(c->metrics.settling5S), 8, 'f', 1);
    };
    for (const TuneRow &r : rows) {
        const bool faster = r.defaults && r.suggested && r.suggested->riseS() < r.defaults->riseS();
        std::fprintf(stderr, "%-9s %-5s %6.1f %5d | %s | %s | %s\n", qPrintable(key(r.drive)),
                     r.loop == StepLoop::Position ? "pos" : "speed", r.seconds, r.candidates,
                     qPrintable(cell(r.defaults, r.loop)), qPrintable(cell(r.suggested, r.loop)),
                     faster ? "yes" : "NO");
    }
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_LOGGING_RULES", "lk.*.info=false");
    QCoreApplication app(argc, argv);
    const bool positionOnly = app.arguments().contains(QStringLiteral("position"));
    QStringList motors;
    QVector<Drive> drives;
    for (const Drive &d : kDrives)
        drives.append(d);
    for (const Drive &d : kPositionDrives)
        drives.append(d);
    for (const Drive &d : drives)
        motors << QStringLiteral("%1:%2%3%4")
                      .arg(d.id)
                      .arg(protocol::seriesName(d.series))
                      .arg(d.v235 ? QStringLiteral("@2.35") : QString())
                      .arg(*d.plant ? QStringLiteral("+") + QLatin1String(d.plant) : QString());
    e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
    if (!sim.start({"--motors", motors.join(QLatin1Char(',')), "--wire-time", "--baud",
                    QString::number(kBaud)})) {
        std::fprintf(stderr, "bench_tuning: %s\n", qPrintable(sim.errorString()));
        return 1;
    }
    bus::BusSession session;
    if (!bench::openSerial(session, sim.devicePath(), kBaud))
        return 1;
    for (const Drive &d : drives) {
        session.send(*protocol::build::plain(protocol::Command::ReadModel, d.id).request);
    }
    bench::waitUntil([&] { return session.knownMotors().size() >= int(drives.size()); }, 10000);
    bench::JsonLine json;
    bool ok = true;
    for (const Drive &d : kPositionDrives)
        ok = bode(session, d, json) && ok;
    QVector<TuneRow> rows;
    if (!positionOnly) {
        for (const Drive &d : kDrives) {
            if (d.series == Series::MF || d.series == Series::MG) // the resonant MF too
                ok = bode(session, d, json) && ok;
        }
        for (const Drive &d : kDrives)
            ok = tune(session, d, StepLoop::Speed, json, rows) && ok;
    }
    // The position loop's search on each series of each generation (not the resonant MF).
    for (const Drive &d : kDrives)
        if (!*d.plant)
            ok = tune(session, d, StepLoop::Position, json, rows) && ok;
    printTable(rows);
    json.print();
    return ok ? 0 : 1;
}
