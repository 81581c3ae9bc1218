// Emergency stop latency: four drives turning at 360 dps on lksim (pseudo-terminal, wire-time
// emulation, 500 us turnaround), known from a scan, through SerialTransport and BusSession.
// Each trial starts the four motors, then times BusSession::emergencyStop() to the first and
// to the last of the four drives' motor_off acknowledgements, and to the end of the stop
// (every ID 1..32 answered or timed out). 20 trials at 115200 and at 1000000 baud.
//
// Prints one JSON line, per baud B:
//   estop_first_ms_median_B, estop_first_ms_max_B   stop() to the first drive's acknowledge
//   estop_last_ms_median_B,  estop_last_ms_max_B    stop() to the last of the four drives'
//   estop_done_ms_median_B                          stop() to emergencyStopFinished
//   estop_ids_sent_B                                motor_off requests sent per stop (min)
//   estop_drives_missed_B                           drive acknowledgements missing, all trials

#include "BenchUtil.h"
#include "LksimProcess.h"

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <transport/SerialTransport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>
#include <QtCore/QSet>

#include <cstdio>

using namespace lk;
using namespace lk::bus;

namespace {

constexpr int kTrials = 20;
const QVector<int> kDrives{1, 2, 3, 4};

struct StopFigures {
    std::vector<double> firstMs, lastMs, doneMs;
    int idsSent = 32;
    int missed = 0;
    bool ok = true;
};

/// Start every drive at 360 dps and wait until each acknowledged.
bool spin(BusSession &session)
{
    QSet<quint64> tickets;
    int acknowledged = 0;
    auto c = QObject::connect(&session, &BusSession::requestCompleted, [&](const RequestResult &r) {
        if (tickets.contains(r.ticket) && r.ok())
            ++acknowledged;
    });
    for (int id : kDrives)
        tickets.insert(session.send(*protocol::build::speed(id, 360).request));
    const bool ok = bench::waitUntil([&] { return acknowledged == kDrives.size(); }, 10000);
    QObject::disconnect(c);
    bench::spin(50); // turning
    return ok;
}

/// One stop: fills first/last/done times; false when it did not finish.
bool timeOneStop(BusSession &session, StopFigures &f)
{
    QElapsedTimer clock;
    quint64 ticket = 0;
    QVector<double> ackMs;
    int sent = 0;
    bool done = false;
    double doneMs = 0;
    auto c1 =
        QObject::connect(&session, &BusSession::requestCompleted, [&](const RequestResult &r) {
            if (r.ticket != ticket)
                return;
            sent += r.attempts > 0 ? 1 : 0;
            if (r.ok() && kDrives.contains(r.request.id))
                ackMs.append(clock.nsecsElapsed() * 1e-6);
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
    QObject::disconnect(c1);
    QObject::disconnect(c2);
    if (!finished)
        return false;
    f.missed += int(kDrives.size() - ackMs.size());
    if (!ackMs.isEmpty()) {
        f.firstMs.push_back(*std::min_element(ackMs.cbegin(), ackMs.cend()));
        f.lastMs.push_back(*std::max_element(ackMs.cbegin(), ackMs.cend()));
    }
    f.doneMs.push_back(doneMs);
    f.idsSent = std::min(f.idsSent, sent);
    return true;
}

StopFigures stops(int baud)
{
    StopFigures f;
    e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
    if (!sim.start({"--motors", "1:MF,2:MG,3:MF,4:MG", "--wire-time", "--baud",
                    QString::number(baud), "--reply-delay-us", "500"})) {
        std::fprintf(stderr, "bench_estop: %s\n", qPrintable(sim.errorString()));
        f.ok = false;
        return f;
    }
    BusSession session;
    transport::SerialSettings s;
    s.portName = sim.devicePath();
    s.baud = baud;
    session.open(transport::SerialTransport::factory(s), baud);
    if (!bench::waitUntil([&] { return session.connection().isOpen(); }, 10000)) {
        f.ok = false;
        return f;
    }
    // lkstudio scans first: the drives are known, so their offs go first.
    bool scanned = false;
    auto c = QObject::connect(&session, &BusSession::scanFinished,
                              [&scanned](const ScanSummary &) { scanned = true; });
    session.scan();
    bench::waitUntil([&] { return scanned; }, 60000);
    QObject::disconnect(c);
    for (int i = 0; i < kTrials && f.ok; ++i)
        f.ok = spin(session) && timeOneStop(session, f);
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
    QCoreApplication app(argc, argv);
    bench::JsonLine json;
    for (int baud : {115200, 1000000}) {
        const StopFigures f = stops(baud);
        if (!f.ok) {
            std::fprintf(stderr, "bench_estop: the stops at %d baud did not run\n", baud);
            return 1;
        }
        const QString b = QString::number(baud);
        json.add(QStringLiteral("estop_first_ms_median_") + b, bench::median(f.firstMs), 2);
        json.add(QStringLiteral("estop_first_ms_max_") + b, maxOf(f.firstMs), 2);
        json.add(QStringLiteral("estop_last_ms_median_") + b, bench::median(f.lastMs), 2);
        json.add(QStringLiteral("estop_last_ms_max_") + b, maxOf(f.lastMs), 2);
        json.add(QStringLiteral("estop_done_ms_median_") + b, bench::median(f.doneMs), 1);
        json.addInt(QStringLiteral("estop_ids_sent_") + b, f.idsSent);
        json.addInt(QStringLiteral("estop_drives_missed_") + b, f.missed);
    }
    json.print();
    return 0;
}
