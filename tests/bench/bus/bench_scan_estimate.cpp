// The scan estimate against what scans take on lkstudio's built-in simulated bus (the
// default four drives at IDs 1..4, wire time at the scanned baud, SimBusHandle through
// BusSession on its own thread, as the GUI has it): the figures behind ScanControls' "Scan
// takes about ...". Each case scans three times from a fresh session and reports the median.
//
// Prints one JSON line: for each case <name>_estimate_ms (before any scan: every ID
// silent), <name>_estimate_known_ms (the drives of the first scan expected where they
// answered, as ScanControls estimates the next scan), <name>_actual_ms (median of 3),
// <name>_drives (drives counted, Scanner::driveCount) and <name>_hits (answers).
// BENCH_SPEC=1:MF,... scans another simulated bus (the default has a V2.35 drive).
//
//   cmake --build build --target run_bench_scan_estimate

#include "BenchUtil.h"

#include <bus/BusConfig.h>
#include <bus/BusSession.h>
#include <bus/Scanner.h>
#include <transport/SimBusHandle.h>

#include <QtCore/QCoreApplication>

#include <cstdio>

using namespace lk;
using namespace lk::bus;

namespace {

struct Case {
    const char *name;
    int baud;
    int firstId;
    int lastId;
    bool sweep;
};

struct Figure {
    double estimateMs = 0;
    double estimateKnownMs = 0;
    std::vector<double> actualMs;
    int drives = 0;
    int hits = 0;
    bool ok = true;
};

Figure measure(const Case &c, int runs)
{
    Figure f;
    ScanOptions o;
    o.firstId = c.firstId;
    o.lastId = c.lastId;
    o.sweepBauds = c.sweep;
    f.estimateMs = 1e3 * Scanner::estimatedSeconds(o, c.baud, BusConfig{});
    const QString specText = qEnvironmentVariableIsSet("BENCH_SPEC")
                                 ? qEnvironmentVariable("BENCH_SPEC")
                                 : transport::SimBusHandle::defaultSpecText();
    const sim::SimBusSpec spec = *sim::SimBusSpec::parse(specText);
    for (int i = 0; i < runs; ++i) {
        auto handle = std::make_shared<transport::SimBusHandle>(spec);
        BusSession session;
        session.open(transport::SimBusHandle::factory(handle), c.baud);
        if (!bench::waitUntil([&] { return session.connection().isOpen(); }, 10000)) {
            f.ok = false;
            return f;
        }
        std::optional<ScanSummary> summary;
        QObject::connect(&session, &BusSession::scanFinished,
                         [&summary](const ScanSummary &s) { summary = s; });
        session.scan(o);
        bench::waitUntil([&] { return summary.has_value(); }, 120000);
        session.close();
        if (!summary || !summary->error.isEmpty()) {
            f.ok = false;
            return f;
        }
        f.actualMs.push_back(summary->elapsedS * 1e3);
        QMap<int, int> answering;
        for (const FoundMotor &m : summary->motors)
            ++answering[m.baud];
        f.estimateKnownMs = 1e3 * Scanner::estimatedSeconds(o, c.baud, BusConfig{}, answering);
        f.drives = Scanner::driveCount(summary->motors);
        f.hits = int(summary->motors.size());
    }
    return f;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const Case cases[] = {
        {"ids32_115200", 115200, 1, 32, false}, {"ids32_1000000", 1000000, 1, 32, false},
        {"ids32_9600", 9600, 1, 32, false},     {"ids8_57600", 57600, 1, 8, false},
        {"sweep_ids32", 115200, 1, 32, true},   {"sweep_ids4", 115200, 1, 4, true},
    };
    bench::JsonLine json;
    for (const Case &c : cases) {
        const Figure f = measure(c, 3);
        if (!f.ok) {
            std::fprintf(stderr, "bench_scan_estimate: %s did not run\n", c.name);
            return 1;
        }
        const QString name = QString::fromLatin1(c.name);
        json.add(name + QStringLiteral("_estimate_ms"), f.estimateMs, 0);
        json.add(name + QStringLiteral("_estimate_known_ms"), f.estimateKnownMs, 0);
        json.add(name + QStringLiteral("_actual_ms"), bench::median(f.actualMs), 0);
        json.addInt(name + QStringLiteral("_drives"), f.drives);
        json.addInt(name + QStringLiteral("_hits"), f.hits);
    }
    json.print();
    return 0;
}
