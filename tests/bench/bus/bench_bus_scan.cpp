// Full scan of IDs 1..32 at 115200 baud with 3 drives present (3, 17, 32), lksim on a
// pseudo-terminal with wire-time emulation and the slowest turnaround a real drive has
// (500 us), through SerialTransport and BusSession. Then the same with drives that answer
// after 5 ms and 16 ms (slow drives: their replies are on the wire that late), and behind a
// slow USB adapter (lksim --adapter-latency-us: the host sees each reply 16 ms after it left
// the wire, FTDI's default latency timer), where a scan must still find every drive, only
// slower.
//
// Prints one JSON line:
//   scan_ms_115200       median of 50 scans      scan_missed_ids  IDs missed over those 50
//   scan_ms_max_115200   slowest of the 50       scan_collisions  requests lksim received
//                                                while a reply was due or on the wire
//   scan_ms_delay5ms, scan_missed_ids_delay5ms, scan_collisions_delay5ms, and the same for
//   delay16ms and adapter16ms: median, misses and collisions over 5 scans each

#include "BenchUtil.h"
#include "LksimProcess.h"

#include <bus/BusSession.h>
#include <transport/SerialTransport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QSet>

#include <cstdio>

using namespace lk;
using namespace lk::bus;

namespace {

const QSet<int> kPresent{3, 17, 32};

struct ScanFigure {
    std::vector<double> ms;
    int missed = 0;         ///< present IDs not found, plus absent IDs reported (never expected)
    qint64 collisions = -1; ///< counted by lksim; -1: unknown
    bool ok = true;
};

ScanFigure scans(int replyDelayUs, int adapterLatencyUs, int count)
{
    ScanFigure f;
    e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
    if (!sim.start({"--motors", "3:MF,17:MS,32:MG", "--wire-time", "--baud", "115200",
                    "--reply-delay-us", QString::number(replyDelayUs), "--adapter-latency-us",
                    QString::number(adapterLatencyUs)})) {
        std::fprintf(stderr, "bench_bus_scan: %s\n", qPrintable(sim.errorString()));
        f.ok = false;
        return f;
    }
    BusSession session;
    transport::SerialSettings s;
    s.portName = sim.devicePath();
    session.open(transport::SerialTransport::factory(s), 115200);
    if (!bench::waitUntil([&] { return session.connection().isOpen(); }, 10000)) {
        f.ok = false;
        return f;
    }
    for (int i = 0; i < count; ++i) {
        std::optional<ScanSummary> summary;
        auto c = QObject::connect(&session, &BusSession::scanFinished,
                                  [&summary](const ScanSummary &s) { summary = s; });
        session.scan();
        bench::waitUntil([&] { return summary.has_value(); }, 60000);
        QObject::disconnect(c);
        if (!summary || !summary->error.isEmpty()) {
            f.ok = false;
            return f;
        }
        QSet<int> found;
        for (const FoundMotor &m : summary->motors)
            found.insert(m.id);
        f.missed += int((kPresent - found).size() + (found - kPresent).size());
        f.ms.push_back(summary->elapsedS * 1e3);
    }
    session.close();
    sim.stop();
    if (const std::optional<e2e::LksimCounters> c = sim.counters())
        f.collisions = c->collisions;
    return f;
}

void add(bench::JsonLine &json, const QString &suffix, const ScanFigure &f)
{
    json.add(QStringLiteral("scan_ms_") + suffix, bench::median(f.ms), 1);
    json.addInt(QStringLiteral("scan_missed_ids_") + suffix, f.missed);
    json.addInt(QStringLiteral("scan_collisions_") + suffix, f.collisions);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const ScanFigure fast = scans(500, 0, 50);
    const ScanFigure d5 = scans(5000, 0, 5);
    const ScanFigure d16 = scans(16000, 0, 5);
    const ScanFigure a16 = scans(500, 16000, 5);
    if (!fast.ok || !d5.ok || !d16.ok || !a16.ok) {
        std::fprintf(stderr, "bench_bus_scan: a scan failed to run\n");
        return 1;
    }
    bench::JsonLine json;
    json.add(QStringLiteral("scan_ms_115200"), bench::median(fast.ms), 1);
    json.addInt(QStringLiteral("scan_missed_ids"), fast.missed);
    json.add(QStringLiteral("scan_ms_max_115200"),
             *std::max_element(fast.ms.begin(), fast.ms.end()), 1);
    json.addInt(QStringLiteral("scan_collisions"), fast.collisions);
    add(json, QStringLiteral("delay5ms"), d5);
    add(json, QStringLiteral("delay16ms"), d16);
    add(json, QStringLiteral("adapter16ms"), a16);
    json.print();
    return 0;
}
