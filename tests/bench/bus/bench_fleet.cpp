// Parameters across the bus (core/fleet) on lksim over a pseudo-terminal, with wire-time
// emulation and the slowest turnaround a real drive has (500 us), through SerialTransport and
// BusSession as lkctl and lkstudio use them:
//   - reading every parameter of 32 V2.3 drives at 115200 baud (target <= 2 s),
//   - reading every parameter of 32 V2.35 drives at 1 Mbaud (target <= 3 s),
//   - restoring 32 V2.35 drives to RAM at 1 Mbaud, every value changing, with the targets
//     read first and read back after (target <= 5 s).
// Each figure is printed beside its physical limit: the sum of the transactions it sent,
// each (request + reply bytes) x 10 / baud + 0.5 ms (docs/ARCHITECTURE.md, the bus limit).
//
// Prints one JSON line: read_v23_115200_ms, read_v23_115200_limit_ms, read_v235_1M_ms,
// read_v235_1M_limit_ms, restore_v235_1M_ms (prepare + write + read-back),
// restore_v235_1M_limit_ms, restore_write_ms (write + read-back alone), drives_read_ok,
// drives_verified, collisions (lksim: requests while a reply was due; must be 0).

#include "BenchSession.h"
#include "BenchUtil.h"
#include "LksimProcess.h"

#include <bus/BusTiming.h>
#include <fleet/FleetReader.h>
#include <fleet/FleetRestore.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>

#include <cstdio>

using namespace lk;

namespace {

using protocol::Generation;

QString motors(const QString &model)
{
    QStringList list;
    for (int id = 1; id <= 32; ++id)
        list << QStringLiteral("%1:%2").arg(id).arg(model);
    return list.join(QLatin1Char(','));
}

/// The wire time and turnaround of one complete read of a drive: read_model and the reads
/// of its generation.
double readLimitS(Generation g, int baud)
{
    const int modelReply = g == Generation::V2_3 ? 5 + 42 + 1 : 5 + 58 + 1;
    double s = bus::BusTiming::transactionTimeS(5, modelReply, baud);
    for (const protocol::Request &r : fleet::FleetCatalog::reads(1, g, std::nullopt))
        s += bus::BusTiming::transactionTimeS(r.command, baud);
    return s;
}

struct Run {
    e2e::LksimProcess sim{QStringLiteral(LKSIM_PATH)};
    bus::BusSession session;
    bool open(const QString &model, int baud)
    {
        if (!sim.start({"--motors", motors(model), "--wire-time", "--baud", QString::number(baud),
                        "--reply-delay-us", "500", "--param-seed", "24"})) {
            std::fprintf(stderr, "bench_fleet: %s\n", qPrintable(sim.errorString()));
            return false;
        }
        return bench::openSerial(session, sim.devicePath(), baud);
    }
    qint64 collisions()
    {
        session.close();
        sim.stop();
        const auto c = sim.counters();
        return c ? c->collisions : -1;
    }
};

QVector<int> allIds()
{
    QVector<int> ids;
    for (int id = 1; id <= 32; ++id)
        ids << id;
    return ids;
}

/// Reads every drive; returns ms (and how many were read completely).
double readAll(bus::BusSession &session, QVector<fleet::DriveSnapshot> *out)
{
    fleet::FleetReader reader(&session);
    bool done = false;
    QObject::connect(&reader, &fleet::FleetReader::finished, [&] { done = true; });
    QElapsedTimer t;
    t.start();
    reader.start(allIds());
    bench::waitUntil([&] { return done; }, 120000);
    const double ms = t.nsecsElapsed() / 1e6;
    *out = reader.snapshots();
    return ms;
}

int complete(const QVector<fleet::DriveSnapshot> &drives)
{
    return int(std::count_if(drives.begin(), drives.end(),
                             [](const fleet::DriveSnapshot &d) { return d.complete(); }));
}

/// Reads all 32 drives of `run` and adds the time and its limit to `line` as `name`_ms and
/// `name`_limit_ms.
QVector<fleet::DriveSnapshot> measureRead(Run &run, Generation g, int baud, const QString &name,
                                          bench::JsonLine &line)
{
    QVector<fleet::DriveSnapshot> drives;
    line.add(name + QStringLiteral("_ms"), readAll(run.session, &drives), 1);
    line.add(name + QStringLiteral("_limit_ms"), 32 * readLimitS(g, baud) * 1000, 1);
    return drives;
}

/// Every drive gets its neighbour's values (all of them change): prepare (the targets read),
/// RAM write and read-back, timed together and without the prepare.
void measureRestore(Run &run, const QVector<fleet::DriveSnapshot> &drives, bench::JsonLine &line)
{
    QVector<fleet::FleetRestore::Job> jobs;
    for (int i = 0; i < drives.size(); ++i)
        jobs << fleet::FleetRestore::Job{drives.at((i + 1) % drives.size()), drives.at(i).id()};
    fleet::FleetRestore restore(&run.session);
    bool prepared = false;
    bool finished = false;
    QObject::connect(&restore, &fleet::FleetRestore::prepared, [&] { prepared = true; });
    QObject::connect(&restore, &fleet::FleetRestore::finished, [&] { finished = true; });
    QElapsedTimer t;
    t.start();
    restore.prepare(jobs);
    bench::waitUntil([&] { return prepared; }, 120000);
    const qint64 prepareNs = t.nsecsElapsed();
    restore.execute(false);
    bench::waitUntil([&] { return finished; }, 120000);
    const double totalMs = t.nsecsElapsed() / 1e6;
    double writeLimitS = 0;
    for (const fleet::RestorePlan &p : restore.plans()) {
        const auto frames = fleet::FleetCatalog::writes(
            p.targetId(), Generation::V2_35, p.source.valueMap(), p.changedKeys(), false);
        for (const fleet::ParamFrame &f : frames)
            writeLimitS += bus::BusTiming::transactionTimeS(f.request.command, 1000000);
    }
    const double limitMs = (2 * 32 * readLimitS(Generation::V2_35, 1000000) + writeLimitS) * 1000;
    line.add(QStringLiteral("restore_v235_1M_ms"), totalMs, 1);
    line.add(QStringLiteral("restore_v235_1M_limit_ms"), limitMs, 1);
    line.add(QStringLiteral("restore_write_ms"), totalMs - prepareNs / 1e6, 1);
    line.addInt(QStringLiteral("drives_verified"),
                std::count_if(restore.reports().begin(), restore.reports().end(),
                              [](const fleet::DriveReport &r) {
                                  return r.outcome == fleet::DriveReport::Outcome::Verified;
                              }));
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    bench::JsonLine line;
    qint64 collisions = 0;
    int readOk = 0;
    {
        Run run;
        if (!run.open(QStringLiteral("MF"), 115200))
            return 1;
        readOk += complete(
            measureRead(run, Generation::V2_3, 115200, QStringLiteral("read_v23_115200"), line));
        collisions += run.collisions();
    }
    {
        Run run;
        if (!run.open(QStringLiteral("MS4015@2.35"), 1000000))
            return 1;
        const QVector<fleet::DriveSnapshot> drives =
            measureRead(run, Generation::V2_35, 1000000, QStringLiteral("read_v235_1M"), line);
        readOk += complete(drives);
        measureRestore(run, drives, line);
        collisions += run.collisions();
    }
    line.addInt(QStringLiteral("drives_read_ok"), readOk);
    line.addInt(QStringLiteral("collisions"), collisions);
    line.print();
    return 0;
}
