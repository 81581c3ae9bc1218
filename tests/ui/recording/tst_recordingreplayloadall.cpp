// "Load all" on its worker thread: it gives every sample and ends with finished; pause, seek
// and close stop it where it got to (nothing handed on is lost, nothing is emitted after the
// stop, playback is paused there); opening another file while it runs starts afresh.
#include <recording/RecordEncoder.h>
#include <recording/RecordFile.h>
#include <recording/RecordingReplay.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <algorithm>

using namespace lk;
using recording::RecordEvent;

namespace {

constexpr int kPairs = 200000; // 100 s of one drive polled every 500 us

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

/// kPairs read_state2 requests of drive 1, each answered 200 us later.
bool writeRecording(const QString &path)
{
    recording::RecordingHeader h;
    h.toolVersion = QStringLiteral("test");
    h.linkDescription = QStringLiteral("test @ 1000000");
    h.baud = 1000000;
    h.context = {{1, protocol::Series::MF, protocol::Generation::V2_3}};
    const QByteArray request = hex("3E 9C 01 00 DB");
    const QByteArray reply = hex("3E 9C 01 07 E2 1E 00 08 0C FE FF 3F 6E");
    recording::RecordFile file;
    if (file.create(path) || file.write(recording::RecordEncoder::encodeHeader(h)))
        return false;
    recording::RecordEncoder enc;
    qint64 blockStart = 0;
    for (int i = 0; i < kPairs; ++i) {
        const qint64 t = qint64(i) * 500'000;
        if (!enc.isEmpty() && (enc.pendingBytes() >= 64 * 1024 || t - blockStart >= 1'000'000'000))
            if (file.write(enc.takeBlock()))
                return false;
        if (enc.isEmpty())
            blockStart = t;
        enc.append(RecordEvent::data(RecordEvent::Kind::Tx, t, request));
        enc.append(RecordEvent::data(RecordEvent::Kind::Rx, t + 200'000, reply));
    }
    const bool ok = !file.write(enc.takeBlock());
    file.close();
    return ok;
}

/// Samples counted as the views would take them.
struct Taken {
    qint64 samples = 0;
    qint64 rows = 0;
    double lastTime = -1;
    bool ordered = true;
    void take(const bus::TelemetryBatch &b)
    {
        for (const bus::TelemetrySample &s : b) {
            ordered = ordered && s.time >= lastTime;
            lastTime = s.time;
        }
        samples += b.size();
    }
};

} // namespace

class tst_RecordingReplayLoadAll : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_path = m_dir.filePath(QStringLiteral("poll.lkrec"));
        QVERIFY(writeRecording(m_path));
    }

    void loadAllGivesEverySampleAndFinishes()
    {
        ui::RecordingReplay replay;
        Taken taken;
        connect(&replay, &ui::RecordingReplay::telemetryReceived, this,
                [&taken](const bus::TelemetryBatch &b) { taken.take(b); });
        connect(&replay, &ui::RecordingReplay::trafficCaptured, this,
                [&taken](const bus::TrafficBatch &b) { taken.rows += b.size(); });
        QSignalSpy finished(&replay, &ui::RecordingReplay::finished);
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        replay.loadAll();
        QVERIFY(replay.isLoadingAll());
        QVERIFY(!replay.isPaused());
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.count(), 1);
        QVERIFY(!replay.isLoadingAll());
        QCOMPARE(taken.samples, qint64(kPairs));
        QCOMPARE(taken.rows, qint64(2 * kPairs));
        QVERIFY(taken.ordered);
        QVERIFY(replay.isFinished());
        QCOMPARE(replay.positionSeconds(), replay.durationSeconds());
    }

    void loadAllHandsOnTheNewestRowsTheViewKeeps()
    {
        // What the Traffic view keeps (setTrafficRowsKept): the newest rows, whole batches of
        // them, handed on when the load ends, and the others counted by kind.
        constexpr qsizetype kKept = 5000;
        ui::RecordingReplay replay;
        replay.setTrafficRowsKept(kKept);
        Taken taken;
        bus::TrafficBatch rows;
        bus::TrafficCounts dropped;
        int droppedSignals = 0;
        bool finishedSeen = false;
        bool rowsAfterFinished = false;
        connect(&replay, &ui::RecordingReplay::telemetryReceived, this,
                [&taken](const bus::TelemetryBatch &b) { taken.take(b); });
        connect(&replay, &ui::RecordingReplay::trafficCaptured, this,
                [&](const bus::TrafficBatch &b) {
                    rows += b;
                    rowsAfterFinished = rowsAfterFinished || finishedSeen;
                });
        connect(&replay, &ui::RecordingReplay::trafficDropped, this,
                [&](const bus::TrafficCounts &c) {
                    dropped += c;
                    ++droppedSignals;
                });
        QSignalSpy finished(&replay, &ui::RecordingReplay::finished);
        connect(&replay, &ui::RecordingReplay::finished, this, [&] { finishedSeen = true; });
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        replay.loadAll();
        QVERIFY(finished.wait(60000));
        QCOMPARE(taken.samples, qint64(kPairs)); // the plots get everything
        QVERIFY(!rowsAfterFinished);             // the rows come before "finished"
        QCOMPARE(droppedSignals, 1);
        QVERIFY(rows.size() >= kKept);
        QVERIFY2(rows.size() < 2 * kKept, qPrintable(QString::number(rows.size())));
        QCOMPARE(qint64(rows.size()) + qint64(dropped.events), qint64(2 * kPairs));
        QCOMPARE(dropped.sent + dropped.frames, dropped.events); // requests and replies only
        // The newest: the last reply of the recording, in order, nothing between lost.
        QCOMPARE(rows.last().time, replay.durationSeconds());
        for (qsizetype i = 1; i < rows.size(); ++i)
            QVERIFY(rows.at(i).time >= rows.at(i - 1).time);
        const double step = 0.0005 / 2; // a request or a reply every 250 us on average
        QVERIFY(rows.last().time - rows.first().time < (rows.size() + 2) * step);
    }

    void statisticsComeAtAWallClockRateAndAtTheEnd()
    {
        // 100 s of recording would give 200 half-second snapshots; Load all sends one every
        // 100 ms of wall time at most, and the figures at the end count every request.
        ui::RecordingReplay replay;
        QVector<bus::ListenStatistics> snapshots;
        QSignalSpy finished(&replay, &ui::RecordingReplay::finished);
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        connect(&replay, &ui::RecordingReplay::listenStatisticsUpdated, this,
                [&snapshots](const bus::ListenStatistics &s) { snapshots.append(s); });
        QElapsedTimer wall;
        wall.start();
        replay.loadAll();
        QVERIFY(finished.wait(60000));
        const qint64 ms = wall.elapsed();
        QVERIFY(!snapshots.isEmpty());
        QVERIFY2(snapshots.size() <= ms / 100 + 2,
                 qPrintable(QStringLiteral("%1 in %2 ms").arg(snapshots.size()).arg(ms)));
        QCOMPARE(snapshots.last().requests, quint64(kPairs));
        QCOMPARE(snapshots.last().paired, quint64(kPairs));
        // Played as usual afterwards (a seek), snapshots follow the recording's clock again.
        replay.seek(0);
        snapshots.clear();
        replay.loadAll();
        QVERIFY(finished.wait(60000));
        QCOMPARE(snapshots.last().requests, quint64(kPairs));
    }

    void aPausedLoadHandsOnItsTailOnce()
    {
        // Paused while the views take its first batch, then loaded again to the end: each load
        // hands on its newest rows and the counts of the others once, rows and counts together
        // are every row decoded, and the rows of the first come before those of the second.
        constexpr qsizetype kKept = 3000;
        ui::RecordingReplay replay;
        replay.setTrafficRowsKept(kKept);
        Taken taken;
        QVector<bus::TrafficBatch> handed;
        QVector<quint64> dropped;
        bool paused = false;
        connect(&replay, &ui::RecordingReplay::telemetryReceived, this,
                [&](const bus::TelemetryBatch &b) {
                    taken.take(b);
                    if (!paused) {
                        paused = true;
                        replay.pause();
                    }
                });
        connect(&replay, &ui::RecordingReplay::trafficCaptured, this,
                [&](const bus::TrafficBatch &b) { handed.append(b); });
        connect(&replay, &ui::RecordingReplay::trafficDropped, this,
                [&](const bus::TrafficCounts &c) { dropped.append(c.events); });
        QSignalSpy finished(&replay, &ui::RecordingReplay::finished);
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        replay.loadAll();
        QTRY_VERIFY(paused);
        QVERIFY(!replay.isLoadingAll());
        QCOMPARE(handed.size(), 1); // the tail, once
        const qint64 firstRows = handed.first().size() + qint64(dropped.value(0));
        QCOMPARE(firstRows, 2 * taken.samples); // a request and a reply per sample so far
        replay.loadAll();
        QVERIFY(finished.wait(60000));
        QCOMPARE(handed.size(), 2);
        QCOMPARE(dropped.size(), 2);
        QCOMPARE(handed[0].size() + handed[1].size() + qint64(dropped[0] + dropped[1]),
                 qint64(2 * kPairs));
        QVERIFY(handed[0].last().time <= handed[1].first().time);
        QCOMPARE(taken.samples, qint64(kPairs));
    }

    void pauseStopsItWhereItGot()
    {
        ui::RecordingReplay replay;
        Taken taken;
        bool pausedInSlot = false;
        // Paused as the first batch reaches the views (a click while the plots fill): the
        // worker is then at most a few batches ahead.
        connect(&replay, &ui::RecordingReplay::telemetryReceived, this,
                [&](const bus::TelemetryBatch &b) {
                    taken.take(b);
                    if (!pausedInSlot) {
                        pausedInSlot = true;
                        replay.pause();
                    }
                });
        QSignalSpy finished(&replay, &ui::RecordingReplay::finished);
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        replay.loadAll();
        QTRY_VERIFY(pausedInSlot);
        QVERIFY(!replay.isLoadingAll());
        QVERIFY(replay.isPaused());
        // What the worker decoded before the stop was delivered by pause() itself: nothing
        // arrives later, and the position is where the samples end.
        const qint64 atPause = taken.samples;
        const double position = replay.positionSeconds();
        qInfo("paused at %lld of %d samples, %.3f s", atPause, kPairs, position);
        QTest::qWait(100);
        QCOMPARE(taken.samples, atPause);
        QCOMPARE(replay.positionSeconds(), position);
        QVERIFY(finished.isEmpty());
        QVERIFY(taken.samples > 0 && taken.samples < kPairs);
        QVERIFY2(taken.lastTime <= position, qPrintable(QString::number(position)));
        // Load all again takes it from there to the end, no sample twice, none lost.
        replay.loadAll();
        QVERIFY(finished.wait(60000));
        QCOMPARE(taken.samples, qint64(kPairs));
        QVERIFY(taken.ordered);
    }

    void aSeekFromASlotComesAfterEverythingBeforeIt()
    {
        // A pause as the first batch arrives, and a seek from the slot that takes the next one
        // (delivered by the pause itself): every batch decoded before the seek reaches the slot
        // before the seek does its work, so nothing from before 50 s comes after it.
        ui::RecordingReplay replay;
        int batches = 0;
        bool sought = false;
        double afterSeekEarliest = 1e9;
        connect(&replay, &ui::RecordingReplay::telemetryReceived, this,
                [&](const bus::TelemetryBatch &b) {
                    ++batches;
                    if (sought) {
                        for (const bus::TelemetrySample &s : b)
                            afterSeekEarliest = std::min(afterSeekEarliest, s.time);
                    }
                    if (batches == 1)
                        replay.pause();
                    else if (batches == 2) {
                        replay.seek(50.0);
                        sought = true;
                    }
                });
        QSignalSpy finished(&replay, &ui::RecordingReplay::finished);
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        replay.loadAll();
        QTRY_VERIFY(sought);
        QVERIFY(!replay.isLoadingAll());
        replay.loadAll();
        QVERIFY(finished.wait(60000));
        QVERIFY2(afterSeekEarliest >= 50.0, qPrintable(QString::number(afterSeekEarliest)));
    }

    void seekAndCloseStopIt()
    {
        ui::RecordingReplay replay;
        Taken taken;
        connect(&replay, &ui::RecordingReplay::telemetryReceived, this,
                [&taken](const bus::TelemetryBatch &b) { taken.take(b); });
        QString error;
        QVERIFY2(replay.open(m_path, options(), &error), qPrintable(error));
        replay.loadAll();
        replay.seek(10.0);
        QVERIFY(!replay.isLoadingAll());
        QVERIFY(replay.isPaused());
        QVERIFY2(qAbs(replay.positionSeconds() - 10.0) < 1e-6,
                 qPrintable(QString::number(replay.positionSeconds())));
        replay.loadAll();
        replay.close();
        QVERIFY(!replay.isLoadingAll());
        QVERIFY(!replay.isOpen());
        const qint64 atClose = taken.samples;
        QTest::qWait(100);
        QCOMPARE(taken.samples, atClose);
        // A file opened while Load all runs starts afresh.
        QVERIFY(replay.open(m_path, options(), &error));
        replay.loadAll();
        QVERIFY(replay.open(m_path, options(), &error));
        QVERIFY(!replay.isLoadingAll());
        QCOMPARE(replay.positionSeconds(), 0.0);
    }

private:
    /// Playing at 1x from the start, as File -> Open does (Load all pauses that timer).
    static recording::ReplayTransport::Options options() { return {}; }

    QTemporaryDir m_dir;
    QString m_path;
};

QTEST_MAIN(tst_RecordingReplayLoadAll)
#include "tst_recordingreplayloadall.moc"
