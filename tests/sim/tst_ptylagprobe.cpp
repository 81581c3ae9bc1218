#include "PtyLagProbe.h"

#include <QtTest/QTest>

#include <algorithm>
#include <poll.h>
#include <time.h>

using lk::app::PtyLagProbe;

namespace {
double monotonicSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}
} // namespace

/// lksim's measure of how long the kernel holds bytes in a pty: canaries through a pty of
/// its own, and what their hold says about bytes read at a given moment.
class tst_PtyLagProbe : public QObject {
    Q_OBJECT
private slots:
    void canariesComeThrough();
    void nothingHeldIsZero();
    void canaryInFlightShowsItsAge();
    void recentArrivalStillCounts();
    void oldArrivalIsForgotten();
    void oneCanaryAtATime();
};

void tst_PtyLagProbe::canariesComeThrough()
{
    PtyLagProbe probe(0.0005);
    QVERIFY2(probe.open(), qPrintable(probe.errorString()));
    // Serve it as lksim does until three canaries have made the round; no time limit on
    // each one (a loaded machine may hold them), only on the whole.
    const double start = monotonicSeconds();
    while (probe.arrivals() < 3 && monotonicSeconds() - start < 10) {
        const double now = monotonicSeconds();
        QVERIFY2(probe.service(now), qPrintable(probe.errorString()));
        pollfd pfd{probe.readFd(), POLLIN, 0};
        const double wait = std::min(0.01, probe.untilNextSendS(now));
        timespec ts{0, static_cast<long>(wait * 1e9)};
        QVERIFY(ppoll(&pfd, 1, &ts, nullptr) >= 0);
    }
    QCOMPARE(probe.arrivals(), 3);
}

void tst_PtyLagProbe::nothingHeldIsZero()
{
    PtyLagProbe probe(0.0005);
    QCOMPARE(probe.heldS(1.0), 0.0);
    probe.noteSent(1.0);
    probe.noteArrived(1.00005); // 50 us: the pty passes bytes at once
    QCOMPARE(probe.heldS(1.0001), 0.0);
    probe.noteSent(1.0006);
    QCOMPARE(probe.heldS(1.0007), 0.0); // in flight for 0.1 ms only
}

void tst_PtyLagProbe::canaryInFlightShowsItsAge()
{
    PtyLagProbe probe(0.0005);
    probe.noteSent(1.0);
    // Still held 3 ms later: bytes read now may have been written 3 ms ago, or up to a
    // period before the canary.
    QVERIFY(qAbs(probe.heldS(1.003) - 0.0035) < 1e-9);
    QVERIFY(probe.untilNextSendS(1.003) > 1.0); // one at a time
}

void tst_PtyLagProbe::recentArrivalStillCounts()
{
    PtyLagProbe probe(0.0005);
    probe.noteSent(1.0);
    probe.noteArrived(1.004);
    // The host's bytes came through in the next wake-up, just after the canary.
    QVERIFY(qAbs(probe.heldS(1.0041) - 0.0045) < 1e-9);
}

void tst_PtyLagProbe::oldArrivalIsForgotten()
{
    PtyLagProbe probe(0.0005);
    probe.noteSent(1.0);
    probe.noteArrived(1.004);
    QCOMPARE(probe.heldS(1.1), 0.0);
}

void tst_PtyLagProbe::oneCanaryAtATime()
{
    PtyLagProbe probe(0.0005);
    QCOMPARE(probe.untilNextSendS(1.0), 0.0);
    probe.noteSent(1.0);
    probe.noteArrived(1.0001);
    // The next one waits for the period, counted from the last one sent.
    QVERIFY(qAbs(probe.untilNextSendS(1.0002) - 0.0003) < 1e-9);
    QCOMPARE(probe.untilNextSendS(1.0006), 0.0);
}

QTEST_GUILESS_MAIN(tst_PtyLagProbe)
#include "tst_ptylagprobe.moc"
