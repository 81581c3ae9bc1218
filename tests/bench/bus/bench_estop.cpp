// Emergency stop latency: four drives at IDs 1, 9, 20 and 31 turning at 360 dps on lksim
// (pseudo-terminal, wire-time emulation, 500 us turnaround), through SerialTransport and
// BusSession, as lkctl or lkstudio would stop them (no IDs given: the bus decides the order).
// Each trial starts the four motors, then times BusSession::emergencyStop() to the first and
// to the last of the four drives' motor_off acknowledgements, and to the end of the stop
// (every ID 1..32 answered or timed out). 20 trials per scenario and baud (115200, 1000000):
//
//   clean  the drives are known from a scan; nothing else happens on the bus
//   scan   the stop comes during a re-scan (which forgot the drives it had found), at a
//          point that moves through the scan from trial to trial
//   drops  lksim drops 10 % of the replies and sends 1 % late (20 ms), drives known
//
// The four drives are polled as lkstudio's dashboard polls them (as fast as the bus allows)
// from the first scan on, so that late replies and timeouts happen just before a stop.
//
// Prints one JSON line; per scenario S and baud B:
//   estop_S_first_ms_median_B, estop_S_first_ms_max_B   stop() to the first drive's acknowledge
//   estop_S_last_ms_median_B,  estop_S_last_ms_max_B    stop() to the last of the four drives'
//   estop_S_done_ms_median_B                            stop() to emergencyStopFinished
//   estop_S_ids_sent_B                                  IDs that got a motor_off per stop (min)
//   estop_S_drives_missed_B                             drives never acknowledged, all trials
//   estop_S_last_ratio_B                                last-drive median over the clean one's
//   estop_S_sent_last_ms_median_B, _max_B               stop() to the last of the four drives'
//                                                       first motor_off on the wire (the traffic
//                                                       capture's send time; what the drive hears
//                                                       even when its acknowledgement is lost)
//   estop_S_sent_last_ratio_B                           that median over the clean one's
//
// The send times are on the bus thread's clock; they are placed on the bench's clock by the
// first acknowledgement (its reply's capture time against its arrival here), which puts them
// late by one hand-over between threads: the figures are, if anything, pessimistic.
//
// Run: build/tests/bench/bus/bench_estop

#include "BenchSession.h"
#include "BenchUtil.h"
#include "LksimProcess.h"

#include <bus/BusSession.h>
#include <bus/PollPlan.h>
#include <bus/TrafficEvent.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>
#include <QtCore/QMap>
#include <QtCore/QSet>

#include <cstdio>
#include <optional>

using namespace lk;
using namespace lk::bus;

namespace {

constexpr int kTrials = 20;
const QVector<int> kDrives{1, 9, 20, 31};

enum class Scenario { Clean, ScanRace, Drops };

struct StopFigures {
    std::vector<double> firstMs, lastMs, doneMs, sentLastMs;
    int idsSent = 32;
    int missed = 0;
    bool ok = true;
};

/// Start every drive at 360 dps and wait until each acknowledged.
bool spin(BusSession &session)
{
    QSet<quint64> tickets;
    QSet<int> acknowledged;
    auto c = QObject::connect(&session, &BusSession::requestCompleted, [&](const RequestResult &r) {
        if (tickets.contains(r.ticket) && r.ok())
            acknowledged.insert(r.request.id);
    });
    for (int id : kDrives)
        tickets.insert(session.send(*protocol::build::speed(id, 360).request));
    bool ok = bench::waitUntil([&] { return acknowledged.size() == kDrives.size(); }, 10000);
    // A lost acknowledgement (drops) does not mean the drive did not start: ask again once.
    for (int id : kDrives)
        if (!acknowledged.contains(id))
            tickets.insert(session.send(*protocol::build::speed(id, 360).request));
    ok = bench::waitUntil([&] { return acknowledged.size() == kDrives.size(); }, 10000);
    QObject::disconnect(c);
    bench::spin(50); // turning
    return ok;
}

bool scanOnce(BusSession &session)
{
    bool scanned = false;
    auto c = QObject::connect(&session, &BusSession::scanFinished,
                              [&scanned](const ScanSummary &) { scanned = true; });
    session.scan();
    const bool ok = bench::waitUntil([&] { return scanned; }, 60000);
    QObject::disconnect(c);
    return ok;
}

/// The last of the four drives' first motor_off on the wire, in ms after stop() (see the
/// header for the clock); nullopt when a drive's send or every reply is missing from `traffic`.
std::optional<double> lastSentMs(const TrafficBatch &traffic, const QMap<int, double> &ackMs)
{
    const quint8 off = quint8(protocol::Command::MotorOff);
    QMap<int, double> sentS, replyS;
    for (const TrafficEvent &e : traffic) {
        if (e.command != off || !kDrives.contains(e.id))
            continue;
        if (e.kind == TrafficEvent::Kind::Sent && !sentS.contains(e.id))
            sentS.insert(e.id, e.time);
        else if (e.kind == TrafficEvent::Kind::Frame && !replyS.contains(e.id))
            replyS.insert(e.id, e.time);
    }
    if (sentS.size() != kDrives.size() || ackMs.isEmpty())
        return std::nullopt;
    int anchor = 0;
    for (auto it = ackMs.cbegin(); it != ackMs.cend(); ++it)
        if (replyS.contains(it.key()) && (anchor == 0 || it.value() < ackMs.value(anchor)))
            anchor = it.key();
    if (anchor == 0)
        return std::nullopt;
    const double offsetMs = ackMs.value(anchor) - replyS.value(anchor) * 1e3;
    double last = 0;
    for (double t : sentS)
        last = std::max(last, t * 1e3 + offsetMs);
    return last;
}

/// One stop: fills first/last/done times; false when it did not finish. `delayMs` >= 0
/// starts a re-scan that long before the stop.
bool timeOneStop(BusSession &session, StopFigures &f, double delayMs)
{
    if (delayMs >= 0) {
        session.scan();
        QElapsedTimer wait;
        wait.start();
        while (wait.nsecsElapsed() < qint64(delayMs * 1e6))
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    }
    QElapsedTimer clock;
    quint64 ticket = 0;
    QMap<int, double> ackMs;
    QSet<int> sent;
    bool done = false;
    double doneMs = 0;
    TrafficBatch traffic;
    auto c0 = QObject::connect(&session, &BusSession::trafficCaptured,
                               [&traffic](const TrafficBatch &b) { traffic += b; });
    auto c1 =
        QObject::connect(&session, &BusSession::requestCompleted, [&](const RequestResult &r) {
            if (r.ticket != ticket)
                return;
            if (r.attempts > 0)
                sent.insert(r.request.id);
            if (r.ok() && kDrives.contains(r.request.id) && !ackMs.contains(r.request.id))
                ackMs.insert(r.request.id, clock.nsecsElapsed() * 1e-6);
        });
    auto c2 = QObject::connect(&session, &BusSession::emergencyStopFinished,
                               [&](quint64 t, const QVector<int> &, const QVector<int> &) {
                                   if (t != ticket)
                                       return;
                                   done = true;
                                   doneMs = clock.nsecsElapsed() * 1e-6;
                               });
    clock.start();
    ticket = session.emergencyStop();
    const bool finished = bench::waitUntil([&] { return done; }, 30000);
    bench::spin(50); // the capture's last batch
    QObject::disconnect(c0);
    QObject::disconnect(c1);
    QObject::disconnect(c2);
    if (!finished)
        return false;
    if (const std::optional<double> ms = lastSentMs(traffic, ackMs))
        f.sentLastMs.push_back(*ms);
    f.missed += int(kDrives.size() - ackMs.size());
    if (!ackMs.isEmpty()) {
        const QList<double> times = ackMs.values();
        f.firstMs.push_back(*std::min_element(times.cbegin(), times.cend()));
        f.lastMs.push_back(*std::max_element(times.cbegin(), times.cend()));
    }
    f.doneMs.push_back(doneMs);
    f.idsSent = std::min(f.idsSent, int(sent.size()));
    return true;
}

QStringList lksimArgs(int baud, Scenario scenario)
{
    QStringList args{"--motors", "1:MF,9:MG,20:MF,31:MG", "--wire-time",
                     "--baud",   QString::number(baud),   "--reply-delay-us",
                     "500"};
    if (scenario == Scenario::Drops)
        args << "--faults"
             << "drop=0.1,delay=0.01,delay_ms=20,seed=7";
    return args;
}

/// How long a scan of 1..32 takes here, for spreading the stops through it.
double scanMs(BusSession &session)
{
    QElapsedTimer t;
    t.start();
    scanOnce(session);
    return t.nsecsElapsed() * 1e-6;
}

StopFigures stops(int baud, Scenario scenario)
{
    StopFigures f;
    e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
    if (!sim.start(lksimArgs(baud, scenario))) {
        std::fprintf(stderr, "bench_estop: %s\n", qPrintable(sim.errorString()));
        f.ok = false;
        return f;
    }
    BusSession session;
    if (!bench::openSerial(session, sim.devicePath(), baud)) {
        f.ok = false;
        return f;
    }
    // lkstudio scans first: the drives are known, and the dashboard polls them.
    const double scanDuration = scanMs(session);
    session.startPolling(PollPlan::standard(kDrives));
    session.setTrafficCapture(true);
    for (int i = 0; i < kTrials && f.ok; ++i) {
        // The stop lands at a point moving through the first 90 % of the re-scan.
        const double delay =
            scenario == Scenario::ScanRace ? scanDuration * 0.9 * (i + 0.5) / kTrials : -1;
        if (!spin(session)) {
            std::fprintf(stderr, "bench_estop: trial %d: the drives did not start\n", i);
            f.ok = false;
        } else if (!timeOneStop(session, f, delay)) {
            std::fprintf(stderr, "bench_estop: trial %d: the stop did not finish\n", i);
            f.ok = false;
        }
        if (f.ok && scenario == Scenario::ScanRace)
            f.ok = scanOnce(session); // the stop cancelled it: learn the drives again
        bench::spin(200);             // polling again, late replies included
    }
    session.close();
    return f;
}

double maxOf(const std::vector<double> &v)
{
    return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_LOGGING_RULES", "lk.bus.info=false"); // one line per stop otherwise
    QCoreApplication app(argc, argv);
    bench::JsonLine json;
    const QList<QPair<Scenario, QString>> scenarios{
        {Scenario::Clean, "clean"}, {Scenario::ScanRace, "scan"}, {Scenario::Drops, "drops"}};
    for (int baud : {115200, 1000000}) {
        const QString b = QString::number(baud);
        double cleanLast = 0, cleanSentLast = 0;
        for (const auto &[scenario, name] : scenarios) {
            const StopFigures f = stops(baud, scenario);
            if (!f.ok) {
                std::fprintf(stderr, "bench_estop: the %s stops at %d baud did not run\n",
                             qPrintable(name), baud);
                return 1;
            }
            const QString k = QStringLiteral("estop_") + name + QLatin1Char('_');
            const double last = bench::median(f.lastMs);
            if (scenario == Scenario::Clean)
                cleanLast = last;
            json.add(k + "first_ms_median_" + b, bench::median(f.firstMs), 2);
            json.add(k + "first_ms_max_" + b, maxOf(f.firstMs), 2);
            json.add(k + "last_ms_median_" + b, last, 2);
            json.add(k + "last_ms_max_" + b, maxOf(f.lastMs), 2);
            json.add(k + "done_ms_median_" + b, bench::median(f.doneMs), 1);
            json.addInt(k + "ids_sent_" + b, f.idsSent);
            json.addInt(k + "drives_missed_" + b, f.missed);
            json.add(k + "last_ratio_" + b, cleanLast > 0 ? last / cleanLast : 0, 2);
            const double sentLast = bench::median(f.sentLastMs);
            if (scenario == Scenario::Clean)
                cleanSentLast = sentLast;
            json.add(k + "sent_last_ms_median_" + b, sentLast, 2);
            json.add(k + "sent_last_ms_max_" + b, maxOf(f.sentLastMs), 2);
            json.add(k + "sent_last_ratio_" + b, cleanSentLast > 0 ? sentLast / cleanSentLast : 0,
                     2);
        }
    }
    json.print();
    return 0;
}
