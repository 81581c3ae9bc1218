// The engine on a CAN link (docs/CAN.md): BusSession over SimTransport with its drives behind
// SimCanFront, emulating the wire time of CAN frames (8 data bytes, worst-case stuffing) at
// the bit rate and answering after the V2.36 document's 0.25 ms, so that a transaction takes
// what LinkTiming charges and a ratio of 1 would mean no host overhead. The bus thread sleeps
// until each reply is due (a timerfd), as it sleeps until a real adapter's frame arrives: the
// host's wake-up is part of every transaction, as it is on hardware and in bench_bus_poll.
//
// Prints one JSON line:
//   poll_ratio_<rate>, poll_txn_per_s_<rate>,   read_state2 from 4 drives (two old CAN, two
//   can_limit_per_s_<rate>                      V2.36): achieved / LinkTiming's CAN limit
//   lost_frames_<rate>                          timeouts + late replies + unexpected frames,
//                                               from the open on (warm-up included)
//   host_overhead_us_<rate>                     1/achieved - 1/limit: the host's time per
//                                               transaction (its wake-up, then the engine)
//   wake_late_us_median, wake_late_us_p90       how late this machine wakes a thread from a
//                                               timerfd set 0.38 ms ahead (a transaction's
//                                               wait), 2000 times: the share of the overhead
//                                               that is the machine's, not the engine's
//   scan_ms_<rate>                              scan of IDs 1..32 with 4 drives, median of 5
//   estop_first_ms, estop_last_ms (median, max) emergency stop with 4 drives turning: until
//                                               the first and the last of them acknowledged
//   estop_all_ms_median                         until every one of 1..32 was sent its Motor Off

#include "BenchUtil.h"

#include <bus/BusSession.h>
#include <bus/LinkTiming.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <transport/PreciseWake.h>
#include <transport/SimTransport.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>

#include <vector>

#include <algorithm>
#include <cstdio>

using namespace lk;
using namespace lk::bus;
using protocol::Command;
using protocol::Generation;
using protocol::Series;

namespace {

constexpr double kMeasureS = 3.0;
const char *kSpec = "1:MG,2:MF,3:MG@2.35,4:MF@2.35";

TransportFactory canFactory()
{
    return [](int bitRate) -> std::unique_ptr<transport::Transport> {
        transport::SimSettings s;
        s.spec = *sim::SimBusSpec::parse(QString::fromLatin1(kSpec));
        s.link = protocol::Link::Can;
        auto t = transport::SimTransport::factory(s)(bitRate);
        static_cast<transport::SimTransport *>(t.get())->setReplyDelay(LinkTiming::kCanReplyTimeS);
        return t;
    };
}

void tellDrives(BusSession &session)
{
    session.setDriveIdentity({1, Series::MG, Generation::V2_3, {}});
    session.setDriveIdentity({2, Series::MF, Generation::V2_3, {}});
    session.setDriveIdentity({3, Series::MG, Generation::V2_35, {}});
    session.setDriveIdentity({4, Series::MF, Generation::V2_35, {}});
}

BusConfig canConfig()
{
    BusConfig c; // as lkctl --can opens it (LiveBus::canConfig)
    c.initialMarginMs = 5;
    c.minMarginMs = 1;
    return c;
}

void pollFigures(int rate, bench::JsonLine &out)
{
    BusSession session;
    tellDrives(session);
    session.open(canFactory(), rate, canConfig());
    bench::waitUntil([&] { return session.connection().isOpen(); }, 5000);
    PollPlan plan = PollPlan::standard({1, 2, 3, 4});
    plan.commands = {Command::ReadState2};
    // The rate counts the replies between two statistics snapshots over the snapshots' own
    // clock: the last snapshot may be up to one statistics period (0.5 s) older than the end
    // of the measurement, so dividing its count by the time measured here would understate
    // the rate by up to a sixth, by chance.
    std::vector<BusStatistics> snapshots;
    QObject::connect(&session, &BusSession::statisticsUpdated,
                     [&snapshots](const BusStatistics &s) { snapshots.push_back(s); });
    session.startPolling(plan);
    bench::spin(500);
    const size_t from = snapshots.size();
    bench::spin(static_cast<int>(kMeasureS * 1000));
    session.stopPolling();
    double achieved = 0;
    BusStatistics a;
    BusStatistics b;
    if (snapshots.size() >= from + 2) {
        a = snapshots[from];
        b = snapshots.back();
        // Less the frames nobody expected, as bench_bus_poll counts (a reply may have been
        // taken for a newer identical request): never below zero.
        const qint64 good =
            std::max<qint64>(0, qint64(b.bus.replies - a.bus.replies) -
                                    qint64(b.bus.unexpectedFrames - a.bus.unexpectedFrames));
        achieved = b.time > a.time ? static_cast<double>(good) / (b.time - a.time) : 0;
    }
    const double limit = LinkTiming::can(rate).transactionsPerSecond({Command::ReadState2});
    const QString r = QString::number(rate / 1000) + QStringLiteral("k");
    out.add(QStringLiteral("poll_ratio_") + r, achieved / limit);
    out.add(QStringLiteral("poll_txn_per_s_") + r, achieved, 0);
    out.add(QStringLiteral("can_limit_per_s_") + r, limit, 0);
    out.add(QStringLiteral("host_overhead_us_") + r,
            achieved > 0 ? 1e6 / achieved - 1e6 / limit : 0, 1);
    // Since the link opened, warm-up included.
    out.addInt(QStringLiteral("lost_frames_") + r,
               qint64(b.bus.timeouts + b.bus.lateReplies + b.bus.unexpectedFrames));
    session.close();
}

void scanFigure(int rate, bench::JsonLine &out)
{
    std::vector<double> ms;
    for (int i = 0; i < 5; ++i) {
        BusSession session;
        session.open(canFactory(), rate, canConfig());
        bench::waitUntil([&] { return session.connection().isOpen(); }, 5000);
        std::optional<ScanSummary> done;
        QObject::connect(&session, &BusSession::scanFinished,
                         [&done](const ScanSummary &s) { done = s; });
        session.scan();
        bench::waitUntil([&] { return done.has_value(); }, 20000);
        if (done && done->motors.size() == 4)
            ms.push_back(done->elapsedS * 1e3);
        session.close();
    }
    const QString r = QString::number(rate / 1000) + QStringLiteral("k");
    out.add(QStringLiteral("scan_ms_") + r, bench::median(ms), 1);
    out.addInt(QStringLiteral("scan_complete_runs_") + r, qint64(ms.size()));
}

void estopFigures(bench::JsonLine &out)
{
    std::vector<double> first;
    std::vector<double> lastOfFour;
    std::vector<double> all;
    for (int i = 0; i < 20; ++i) {
        BusSession session;
        tellDrives(session);
        session.open(canFactory(), 1000000, canConfig());
        bench::waitUntil([&] { return session.connection().isOpen(); }, 5000);
        safety::SoftLimits limits;
        limits.maxTorqueA = 1.0;
        int turning = 0;
        for (int id = 1; id <= 4; ++id) {
            session.setSoftLimits(id, limits);
            session.send(*protocol::build::speed(id, 360).request, &session,
                         [&turning](const RequestResult &r) { turning += r.ok() ? 1 : 0; });
        }
        bench::waitUntil([&] { return turning == 4; }, 5000);
        QElapsedTimer t;
        double firstMs = -1;
        double lastMs = -1;
        std::optional<double> allMs;
        QObject::connect(&session, &BusSession::emergencyStopProgress,
                         [&](quint64, const QVector<int> &acked, const QVector<int> &, int) {
                             const auto of4 = std::count_if(acked.begin(), acked.end(),
                                                            [](int id) { return id <= 4; });
                             if (of4 >= 1 && firstMs < 0)
                                 firstMs = t.nsecsElapsed() * 1e-6;
                             if (of4 == 4 && lastMs < 0)
                                 lastMs = t.nsecsElapsed() * 1e-6;
                         });
        QObject::connect(&session, &BusSession::emergencyStopFinished,
                         [&](quint64, const QVector<int> &, const QVector<int> &,
                             const QVector<int> &) { allMs = t.nsecsElapsed() * 1e-6; });
        t.start();
        session.emergencyStop();
        bench::waitUntil([&] { return allMs.has_value(); }, 10000);
        if (firstMs >= 0 && lastMs >= 0 && allMs) {
            first.push_back(firstMs);
            lastOfFour.push_back(lastMs);
            all.push_back(*allMs);
        }
        session.close();
    }
    out.add(QStringLiteral("estop_first_ms_median"), bench::median(first), 2);
    out.add(QStringLiteral("estop_first_ms_max"),
            first.empty() ? 0 : *std::max_element(first.begin(), first.end()), 2);
    out.add(QStringLiteral("estop_last_ms_median"), bench::median(lastOfFour), 2);
    out.add(QStringLiteral("estop_last_ms_max"),
            lastOfFour.empty() ? 0 : *std::max_element(lastOfFour.begin(), lastOfFour.end()), 2);
    out.add(QStringLiteral("estop_all_ms_median"), bench::median(all), 2);
    out.addInt(QStringLiteral("estop_runs"), qint64(all.size()));
}

/// The machine's own wake-up latency, beside which the host overhead above is read.
void wakeFigures(bench::JsonLine &out)
{
    constexpr qint64 kWaitNs = 380000; // about a CAN transaction: two frames and 0.25 ms
    transport::PreciseWake wake;
    if (!wake.isValid())
        return;
    std::vector<double> lateUs;
    QElapsedTimer clock;
    bool woke = false;
    QObject::connect(&wake, &transport::PreciseWake::woke, [&woke] { woke = true; });
    for (int i = 0; i < 2000; ++i) {
        woke = false;
        clock.start();
        wake.wakeIn(kWaitNs);
        while (!woke)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        lateUs.push_back(static_cast<double>(clock.nsecsElapsed() - kWaitNs) / 1e3);
    }
    std::sort(lateUs.begin(), lateUs.end());
    out.add(QStringLiteral("wake_late_us_median"), bench::median(lateUs), 1);
    out.add(QStringLiteral("wake_late_us_p90"), lateUs[lateUs.size() * 9 / 10], 1);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    bench::JsonLine out;
    out.addText(QStringLiteral("bench"), QStringLiteral("can_bus"));
    for (int rate : {1000000, 500000})
        pollFigures(rate, out);
    for (int rate : {1000000, 500000})
        scanFigure(rate, out);
    estopFigures(out);
    wakeFigures(out);
    out.print();
    return 0;
}
