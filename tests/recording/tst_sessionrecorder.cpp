// SessionRecorder: records reach the file in order; a full queue becomes an explicit Dropped
// record; a disk that is full at the start or fills up mid-session stops the recording with a
// typed error; a process killed with SIGKILL leaves a file that opens up to its last flush.
#include "RecordingTestUtil.h"

#include "../support/FileSizeLimit.h"

#include <recording/SessionRecorder.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

using namespace lk::recording;
using lk::testsupport::readAll;
using lk::testsupport::testHeader;

namespace {

RecordEvent rx(qint64 ns, int i)
{
    return RecordEvent::data(RecordEvent::Kind::Rx, ns, QByteArray(13, char(i)));
}

} // namespace

class tst_SessionRecorder : public QObject {
    Q_OBJECT
private slots:
    void recordsReachTheFileInOrder()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.lkrec"));
        SessionRecorder::Limits limits;
        limits.blockBytes = 300; // several blocks
        SessionRecorder recorder(limits);
        QVERIFY(!recorder.start(path, testHeader()));
        QVERIFY(recorder.isRecording());
        for (int i = 0; i < 100; ++i)
            recorder.append(rx(i * 1000, i));
        recorder.stop();
        RecordingError error;
        const auto got = readAll(path, &error);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::None));
        QCOMPARE(got.size(), 100);
        for (int i = 0; i < 100; ++i) {
            QCOMPARE(got.at(i).timeNs, qint64(i * 1000));
            QCOMPARE(got.at(i).bytes, QByteArray(13, char(i)));
        }
    }

    void aFullQueueWritesAnExplicitDroppedRecord()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("d.lkrec"));
        SessionRecorder::Limits limits;
        limits.maxQueuedRecords = 4;
        SessionRecorder recorder(limits);
        QVERIFY(!recorder.start(path, testHeader()));
        recorder.holdWriter(true); // a stalled disk
        for (int i = 0; i < 10; ++i)
            recorder.append(rx(i * 1000, i));
        recorder.holdWriter(false);
        recorder.stop();
        const auto got = readAll(path);
        QCOMPARE(got.size(), 5);
        for (int i = 0; i < 4; ++i)
            QCOMPARE(int(got.at(i).kind), int(RecordEvent::Kind::Rx));
        QCOMPARE(int(got.at(4).kind), int(RecordEvent::Kind::Dropped));
        QCOMPARE(got.at(4).droppedChunks, quint64(6));
        QCOMPARE(got.at(4).droppedBytes, quint64(6 * 13));
        QCOMPARE(got.at(4).timeNs, qint64(4000)); // when the first chunk was lost
        QCOMPARE(recorder.droppedBytes(), quint64(6 * 13));
    }

    void aFullDiskAtStartIsATypedError()
    {
        SessionRecorder recorder;
        const auto error = recorder.start(QStringLiteral("/dev/full"), testHeader());
        QVERIFY(error);
        QCOMPARE(int(error->kind), int(RecordingError::Kind::DiskFull));
        QVERIFY2(error->message.contains(QStringLiteral("/dev/full")), qPrintable(error->message));
        QVERIFY(!recorder.isRecording());
        recorder.append(rx(0, 1)); // ignored, no crash
    }

    void anUnwritablePathIsATypedError()
    {
        SessionRecorder recorder;
        const auto error = recorder.start(QStringLiteral("/nonexistent-dir/x.lkrec"), testHeader());
        QVERIFY(error);
        QCOMPARE(int(error->kind), int(RecordingError::Kind::OpenFailed));
        QVERIFY(error->message.contains(QStringLiteral("/nonexistent-dir/x.lkrec")));
    }

    void aDiskFillingUpMidSessionStopsTheRecording()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("full.lkrec"));
        SessionRecorder::Limits limits;
        limits.blockBytes = 512;
        SessionRecorder recorder(limits);
        QSignalSpy failed(&recorder, &SessionRecorder::recordingFailed);
        lk::testsupport::FileSizeLimit limit(4096);
        if (!limit.isActive())
            QSKIP("setrlimit(RLIMIT_FSIZE) refused");
        QVERIFY(!recorder.start(path, testHeader()));
        for (int i = 0; i < 1000 && failed.isEmpty(); ++i) {
            recorder.append(rx(i * 1000, i));
            if (i % 50 == 49)
                QTest::qWait(5);
        }
        QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 5000);
        const auto error = qvariant_cast<RecordingError>(failed.at(0).at(0));
        QCOMPARE(int(error.kind), int(RecordingError::Kind::DiskFull));
        QVERIFY(!recorder.isRecording());
        QVERIFY(recorder.failure());
        recorder.append(rx(0, 1)); // the session goes on: appends are ignored
        recorder.stop();
        // What reached the disk before it filled still opens.
        RecordingError readError;
        const auto got = readAll(path, &readError);
        QVERIFY(!got.isEmpty());
        QCOMPARE(got.first().bytes, QByteArray(13, char(0)));
    }

    void aKilledProcessLeavesAFileThatOpensToItsLastFlush()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("killed.lkrec"));
        int fds[2];
        QCOMPARE(::pipe(fds), 0);
        const pid_t child = ::fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            // The child records a chunk every 20 ms and says how many it has appended.
            ::close(fds[0]);
            SessionRecorder recorder; // flushes every second
            if (recorder.start(path, testHeader()))
                ::_exit(2);
            for (int i = 0;; ++i) {
                recorder.append(rx(qint64(i) * 20'000'000, i));
                const int n = i + 1;
                if (::write(fds[1], &n, sizeof n) != sizeof n)
                    ::_exit(3);
                ::usleep(20'000);
            }
        }
        ::close(fds[1]);
        // Let it run 2.5 s, then kill it without warning; the last count read is what it had
        // appended by then.
        QElapsedTimer timer;
        timer.start();
        int appended = 0;
        int appendedOneSecondBefore = 0;
        QVector<QPair<qint64, int>> counts;
        while (timer.elapsed() < 2500) {
            int n = 0;
            if (::read(fds[0], &n, sizeof n) != sizeof n)
                break;
            appended = n;
            counts.append({timer.elapsed(), n});
        }
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ::close(fds[0]);
        QVERIFY(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
        const qint64 killedAt = timer.elapsed();
        for (const auto &c : counts)
            if (c.first <= killedAt - 1100)
                appendedOneSecondBefore = c.second;
        RecordingError error;
        const auto got = readAll(path, &error);
        qInfo("appended %d, %d a second before the kill, %d in the file", appended,
              appendedOneSecondBefore, int(got.size()));
        QVERIFY(error.kind == RecordingError::Kind::None ||
                error.kind == RecordingError::Kind::Truncated);
        QVERIFY(appendedOneSecondBefore > 0);
        QVERIFY(got.size() >= appendedOneSecondBefore);
        QVERIFY(got.size() <= appended);
        for (int i = 0; i < got.size(); ++i)
            QCOMPARE(got.at(i).bytes, QByteArray(13, char(i)));
    }
};

QTEST_GUILESS_MAIN(tst_SessionRecorder)
#include "tst_sessionrecorder.moc"
