// Who an emergency stop reaches: always every ID 1..32, the known, commanded, moving and
// answering ones first, whatever a scan has done to the registry; a scan in progress ends
// inside the stop's call. How long it takes: a silent ID costs only what the wire needs, a late
// reply of one drive does not slow it, and its silences are not counted as timeouts.

#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusSession.h>
#include <bus/BusWorker.h>
#include <bus/EmergencyStop.h>
#include <bus/MotorRegistry.h>
#include <bus/StopTargets.h>
#include <protocol/RequestBuilder.h>

#include <atomic>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {
QVector<int> range(int first, int last, const QVector<int> &except = {})
{
    QVector<int> ids;
    for (int id = first; id <= last; ++id) {
        if (!except.contains(id))
            ids.append(id);
    }
    return ids;
}
} // namespace

class tst_EmergencyTargets : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void targetsAlwaysCoverEveryId_data();
    void targetsAlwaysCoverEveryId();
    void registryPutsKnownFirst();
    void onlyKnownAndCommandedAreRetried();
    void stopDuringScanReachesEveryDrive_data();
    void stopDuringScanReachesEveryDrive();
    void closedSessionReportsEveryIdSilent();
    void tallyNamesTheUnsent();
    void stopOnAClosedLinkReportsEveryIdUnsent();
    void stopDuringRescanReachesTheDrivesItSawFirst();
    void lateReplyDoesNotSlowTheStop();
    void stopSilencesAreCountedApart();
    void lostAcknowledgementIsAskedAgainBeforeTheSilentIds();
    void stopDoesNotWaitOutAPollsMargin();
};

namespace {
const QVector<int> kDrives{1, 9, 20, 31};

/// Drives at 1, 9, 20 and 31 answering after `delayMs`, on a clock the test advances.
std::unique_ptr<WorkerRig> fourDrives(int delayMs = 1)
{
    BusConfig c = relaxedConfig();
    c.minMarginMs = 2;
    c.initialMarginMs = 15;
    c.maxMarginMs = 400;
    auto rig = std::make_unique<WorkerRig>(
        [delayMs](FakeTransport &t) {
            for (int id : kDrives)
                t.drives().add(id, Series::MF);
            t.setReplyDelayMs(delayMs);
        },
        c, 115200, RigTime::Manual);
    rig->runUntil([&] { return rig->worker->isOpen(); });
    return rig;
}
} // namespace

void tst_EmergencyTargets::targetsAlwaysCoverEveryId_data()
{
    QTest::addColumn<QVector<int>>("priority");
    QTest::addColumn<QList<int>>("known");
    QTest::addColumn<QVector<int>>("first");

    QTest::newRow("nothing known") << QVector<int>{} << QList<int>{} << QVector<int>{};
    QTest::newRow("known only") << QVector<int>{} << QList<int>{17, 3} << QVector<int>{3, 17};
    QTest::newRow("commanded, not known (scan cleared the registry): commanded first")
        << QVector<int>{4, 2, 3} << QList<int>{1} << QVector<int>{2, 3, 4, 1};
    QTest::newRow("duplicates and invalid IDs")
        << QVector<int>{0, 5, 33, 5, -1} << QList<int>{5, 32} << QVector<int>{5, 32};
}

void tst_EmergencyTargets::targetsAlwaysCoverEveryId()
{
    QFETCH(QVector<int>, priority);
    QFETCH(QList<int>, known);
    QFETCH(QVector<int>, first);
    const StopTargets t = StopTargets::of(priority, known);
    QCOMPARE(t.first, first);
    QCOMPARE(t.others, range(1, 32, first));
    QCOMPARE(t.all().size(), 32);
    QCOMPARE(t.all().mid(0, first.size()), first); // known and commanded go first
}

void tst_EmergencyTargets::registryPutsKnownFirst()
{
    MotorRegistry r;
    r.noteSeen(9);
    r.setSeries(30, Series::MS);
    const StopTargets t = r.emergencyTargets({2});
    QCOMPARE(t.first, (QVector<int>{2, 9, 30}));
    QCOMPARE(t.all().size(), 32);
    r.forget(1, 32); // what a scan does before it finds anything
    // Drive 9 answered on this connection: the scan forgot it, the stop does not.
    QCOMPARE(r.emergencyTargets({}).first, QVector<int>{9});
    QCOMPARE(r.emergencyTargets({}).all().size(), 32);
    // A drive seen moving goes before one that only answered.
    r.noteSeen(31);
    r.noteMotion(31, true);
    QCOMPARE(r.emergencyTargets({}).first, (QVector<int>{31, 9}));
    r.noteMotion(31, false);
    QCOMPARE(r.emergencyTargets({}).first, (QVector<int>{9, 31}));
    QCOMPARE(MotorRegistry().emergencyTargets({}).all(), range(1, 32));
}

void tst_EmergencyTargets::onlyKnownAndCommandedAreRetried()
{
    const EmergencyStop stop(1, StopTargets::of({4}, {}), 2);
    const QVector<BusRequest> requests = stop.requests();
    QCOMPARE(requests.size(), 32);
    QCOMPARE(int(requests.first().request.id), 4);
    for (const BusRequest &r : requests) {
        QCOMPARE(r.request.command, Command::MotorOff);
        QCOMPARE(r.priority, Priority::Emergency);
        QCOMPARE(r.retries, r.request.id == 4 ? 2 : 0);
    }
    // Nothing known: any ID may be a drive, so every one is asked again when silent.
    for (const BusRequest &r : EmergencyStop(2, StopTargets::of({}, {}), 2).requests())
        QCOMPARE(r.retries, 2);
}

void tst_EmergencyTargets::stopDuringScanReachesEveryDrive_data()
{
    QTest::addColumn<int>("probesBeforeStop");
    for (int n : {0, 1, 2, 3, 5, 8})
        QTest::newRow(qPrintable(QStringLiteral("after %1 scan request(s)").arg(n))) << n;
}

void tst_EmergencyTargets::stopDuringScanReachesEveryDrive()
{
    // Four drives; the scan has emptied the registry and found some of them (or none) when
    // the stop comes: every drive must still hear motor_off, and the scan must end with it.
    QFETCH(int, probesBeforeStop);
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 15;
    WorkerRig rig(
        [](FakeTransport &t) {
            for (int id = 1; id <= 4; ++id)
                t.drives().add(id, Series::MF);
            t.setReplyDelayMs(1);
        },
        c, 115200, RigTime::Manual);
    QVERIFY(rig.runUntil([&] { return rig.worker->isOpen(); }));
    QSignalSpy scanned(rig.worker.get(), &BusWorker::scanFinished);
    QSignalSpy stopped(rig.worker.get(), &BusWorker::emergencyStopFinished);
    rig.worker->forgetMotors();
    rig.worker->scan({});
    if (probesBeforeStop > 0)
        QVERIFY(rig.runUntil([&] { return rig.log->writtenCopy().size() >= probesBeforeStop; }));
    rig.worker->emergencyStop(42, {});
    QVERIFY(!rig.worker->isScanning() || rig.worker->isBusy()); // ends with the probe in flight
    QVERIFY(rig.runUntil([&] { return stopped.size() == 1; }, 20000));
    QCOMPARE(stopped.at(0).at(1).value<QVector<int>>(), (QVector<int>{1, 2, 3, 4}));
    QVERIFY(rig.runUntil([&] { return scanned.size() == 1; }, 5000));
    QVERIFY(scanned.at(0).at(0).value<ScanSummary>().cancelled);

    const auto written = rig.writtenRequests();
    const auto firstOff = std::find_if(written.cbegin(), written.cend(),
                                       [](const auto &w) { return w.first == Command::MotorOff; });
    QVERIFY(firstOff != written.cend());
    QSet<int> offs;
    for (auto it = firstOff; it != written.cend(); ++it) {
        // No scan probe after the stop began: the scan ended in the stop's own call.
        QVERIFY2(it->first == Command::MotorOff,
                 qPrintable(QStringLiteral("0x%1 to %2 after the stop")
                                .arg(quint8(it->first), 2, 16)
                                .arg(it->second)));
        offs.insert(it->second);
    }
    QCOMPARE(offs.size(), 32);
}

void tst_EmergencyTargets::closedSessionReportsEveryIdSilent()
{
    BusSession session; // never opened: nothing can be sent
    QSignalSpy finished(&session, &BusSession::emergencyStopFinished);
    session.emergencyStop({3});
    QTRY_COMPARE(finished.size(), 1);
    QVERIFY(finished.at(0).at(1).value<QVector<int>>().isEmpty());
    const QVector<int> silent = finished.at(0).at(2).value<QVector<int>>();
    QCOMPARE(silent.size(), 32);
    QCOMPARE(silent.first(), 3);
    QCOMPARE(finished.at(0).at(3).value<QVector<int>>(), silent); // none reached the wire
}

void tst_EmergencyTargets::tallyNamesTheUnsent()
{
    // The report says how many halts reached the wire: a silent ID whose motor_off was sent
    // and one whose motor_off never left (the link dropped) are told apart.
    EmergencyStop stop(7, StopTargets::of({}, {}), 0);
    bool last = false;
    for (const BusRequest &r : stop.requests()) {
        RequestResult result;
        result.ticket = r.ticket;
        result.request = r.request;
        const int id = r.request.id;
        result.status = id == 2   ? RequestStatus::Ok
                        : id > 30 ? RequestStatus::Disconnected
                                  : RequestStatus::Timeout;
        result.attempts = id > 30 ? 0 : 1;
        QVERIFY(!last);
        last = stop.record(result);
    }
    QVERIFY(last);
    QCOMPARE(stop.acknowledged(), (QVector<int>{2}));
    QCOMPARE(stop.silent(), range(1, 32, {2}));
    QCOMPARE(stop.unsent(), (QVector<int>{31, 32}));
}

void tst_EmergencyTargets::stopOnAClosedLinkReportsEveryIdUnsent()
{
    WorkerRig rig([](FakeTransport &t) { t.setFailOpen(true); });
    QSignalSpy stopped(rig.worker.get(), &BusWorker::emergencyStopFinished);
    rig.worker->emergencyStop(9, {5});
    QTRY_COMPARE(stopped.size(), 1);
    QVERIFY(stopped.at(0).at(1).value<QVector<int>>().isEmpty());
    QCOMPARE(stopped.at(0).at(2).value<QVector<int>>(), range(1, 32));
    QCOMPARE(stopped.at(0).at(3).value<QVector<int>>(), range(1, 32));
    QVERIFY(rig.log->writtenCopy().isEmpty());
}

void tst_EmergencyTargets::stopDuringRescanReachesTheDrivesItSawFirst()
{
    // The four drives were told to turn and answered; a re-scan then emptied the registry.
    // Motor Off reaches them before any ID that never answered, not in ID order behind them.
    auto rig = fourDrives();
    for (int id : kDrives) {
        const quint64 t = rig->send(*protocol::build::speed(id, 360).request);
        QVERIFY(rig->runUntil([&] { return rig->result(t); }));
        QVERIFY(rig->result(t)->ok());
    }
    QSignalSpy stopped(rig->worker.get(), &BusWorker::emergencyStopFinished);
    rig->worker->forgetMotors();
    rig->worker->scan({});
    QVERIFY(rig->runUntil([&] { return rig->log->writtenCopy().size() >= 6; }));
    const int before = rig->log->writtenCopy().size();
    rig->worker->emergencyStop(7, {});
    QVERIFY(rig->runUntil([&] { return stopped.size() == 1; }));
    QVector<int> firstOffs;
    const auto written = rig->writtenRequests();
    for (int i = before; i < written.size() && firstOffs.size() < kDrives.size(); ++i) {
        if (written.at(i).first == Command::MotorOff)
            firstOffs.append(written.at(i).second);
    }
    QCOMPARE(firstOffs, kDrives);
    QCOMPARE(stopped.at(0).at(1).value<QVector<int>>(), kDrives);
}

void tst_EmergencyTargets::lateReplyDoesNotSlowTheStop()
{
    // The four drives answered; then drive 1 answered one poll 150 ms late, just before the
    // stop. Its lift is its own: the stop's 28 silent IDs each wait only for the wire
    // (request, turnaround, reply), and the whole stop is over in well under the 28 x 150 ms
    // a link-wide lift would cost.
    auto rig = fourDrives();
    for (int id : kDrives) {
        const quint64 t = rig->send(plainRequest(Command::ReadState1, id));
        QVERIFY(rig->runUntil([&] { return rig->result(t); }));
    }
    rig->transport->setReplyDelayMs(150);
    const quint64 slow = rig->send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
    QVERIFY(rig->runUntil([&] { return rig->result(slow); }));
    QCOMPARE(rig->result(slow)->status, RequestStatus::Timeout);
    QVERIFY(rig->runUntil([&] { return rig->worker->statisticsSnapshot().bus.lateReplies == 1; },
                          5000));
    rig->transport->setReplyDelayMs(1);
    QSignalSpy stopped(rig->worker.get(), &BusWorker::emergencyStopFinished);
    QSignalSpy progress(rig->worker.get(), &BusWorker::emergencyStopProgress);
    const double start = rig->nowMs();
    rig->worker->emergencyStop(8, {});
    QVERIFY(rig->runUntil([&] { return stopped.size() == 1; }));
    const double tookMs = rig->nowMs() - start;
    QCOMPARE(stopped.at(0).at(1).value<QVector<int>>(), kDrives);
    // 32 IDs, each at most a probe timeout (3.4 ms at 115200) on a whole-millisecond timer.
    QVERIFY2(tookMs < 32 * 5.0, qPrintable(QStringLiteral("%1 ms").arg(tookMs)));
    // Each result but the last came as progress, the acknowledgements among them.
    QCOMPARE(progress.size(), 31);
    QCOMPARE(progress.last().at(3).toInt(), 1);
}

void tst_EmergencyTargets::stopSilencesAreCountedApart()
{
    auto rig = fourDrives();
    for (int id : kDrives) { // every drive has answered on this connection
        const quint64 t = rig->send(plainRequest(Command::ReadState1, id));
        QVERIFY(rig->runUntil([&] { return rig->result(t); }));
    }
    QSignalSpy stopped(rig->worker.get(), &BusWorker::emergencyStopFinished);
    rig->worker->emergencyStop(9, {});
    QVERIFY(rig->runUntil([&] { return stopped.size() == 1; }));
    const BusStatistics st = rig->worker->statisticsSnapshot();
    QCOMPARE(st.bus.timeouts, quint64(0)); // the 28 IDs with no drive are not timeouts
    QCOMPARE(st.bus.silentProbes, quint64(28));
}

void tst_EmergencyTargets::lostAcknowledgementIsAskedAgainBeforeTheSilentIds()
{
    // Drive 9's first acknowledgement is lost (or its "off" was: the host cannot tell). It is
    // asked again right after the other known drives' first "off", not after the 28 IDs where
    // no drive ever answered (some 100 ms at 115200).
    auto rig = fourDrives();
    for (int id : kDrives) {
        const quint64 t = rig->send(plainRequest(Command::ReadState1, id));
        QVERIFY(rig->runUntil([&] { return rig->result(t); }));
    }
    auto dropped = std::make_shared<std::atomic<bool>>(false);
    FakeTransport *tp = rig->transport;
    tp->setResponder([tp, dropped](const protocol::Frame &req, int) {
        if (req.id == 9 && req.command == quint8(Command::MotorOff) && !dropped->exchange(true))
            return QByteArray();
        return tp->defaultReply(req);
    });
    const int before = rig->log->writtenCopy().size();
    QSignalSpy stopped(rig->worker.get(), &BusWorker::emergencyStopFinished);
    rig->worker->emergencyStop(11, {});
    QVERIFY(rig->runUntil([&] { return stopped.size() == 1; }));
    QCOMPARE(stopped.at(0).at(1).value<QVector<int>>(), kDrives); // 9 acknowledged the retry
    QVector<int> order;
    for (const QByteArray &frame : rig->log->writtenCopy().mid(before))
        order.append(quint8(frame.at(2)));
    QCOMPARE(order.mid(0, 5), (QVector<int>{1, 9, 20, 31, 9}));
    QCOMPARE(order.size(), 33);
}

void tst_EmergencyTargets::stopDoesNotWaitOutAPollsMargin()
{
    // Drive 1 answered a read 150 ms late, which lifts its own timeout to some 225 ms. Then a
    // read to it is on the wire when the stop comes, and its reply is lost. The stop waits
    // only until that reply could no longer be on the wire (request and reply wire time plus
    // turnaround, some 2.5 ms at 115200), not for the lifted timeout and a quiet period after.
    auto rig = fourDrives();
    rig->transport->setReplyDelayMs(150);
    const quint64 slow = rig->send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
    QVERIFY(rig->runUntil([&] { return rig->result(slow); }));
    QVERIFY(rig->runUntil([&] { return rig->worker->statisticsSnapshot().bus.lateReplies == 1; },
                          5000));
    rig->transport->setReplyDelayMs(1);
    FakeTransport *tp = rig->transport;
    tp->setResponder([tp](const protocol::Frame &req, int) {
        const bool lost = req.id == 1 && req.command == quint8(Command::ReadState1);
        return lost ? QByteArray() : tp->defaultReply(req);
    });
    const int before = rig->log->writtenCopy().size();
    const quint64 read = rig->send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
    QVERIFY(rig->runUntil([&] { return rig->log->writtenCopy().size() > before; }));
    const double start = rig->nowMs();
    rig->worker->emergencyStop(12, {});
    QVERIFY(rig->runUntil([&] { return rig->log->writtenCopy().size() > before + 1; }));
    const double waitedMs = rig->nowMs() - start;
    QVERIFY2(waitedMs < 5, qPrintable(QStringLiteral("first motor_off after %1 ms").arg(waitedMs)));
    QCOMPARE(quint8(rig->log->writtenCopy().at(before + 1).at(1)), quint8(Command::MotorOff));
    QVERIFY(rig->runUntil([&] { return rig->result(read); }));
    QCOMPARE(rig->result(read)->status, RequestStatus::Timeout);
}

QTEST_GUILESS_MAIN(tst_EmergencyTargets)
#include "tst_emergencytargets.moc"
