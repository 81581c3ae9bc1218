// ReplayTransport on a clock the test advances: chunks arrive at their recorded times scaled
// by the speed, long silences shortened, tx and rx both as received bytes; write() sends
// nothing; seek brings the decode context in force; "load all" plays everything; a damaged
// file plays to its damage.
#include "RecordingTestUtil.h"

#include "../support/ManualTimers.h"

#include <recording/ReplayTransport.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace lk::recording;
namespace protocol = lk::protocol;
using lk::testsupport::ManualClock;
using lk::testsupport::ManualTimers;
using lk::testsupport::testHeader;
using lk::testsupport::writeFile;
using lk::transport::Transport;

namespace {

constexpr qint64 kMs = 1'000'000;

/// A at 0 (tx), B at 10 ms, a context at 3 s, C at 5 s, D at 5.01 s; one block per record.
QByteArray recording(QVector<qsizetype> *ends = nullptr)
{
    QByteArray file = RecordEncoder::encodeHeader(testHeader());
    RecordEncoder enc;
    RecordEvent ctx;
    ctx.kind = RecordEvent::Kind::Context;
    ctx.timeNs = 3000 * kMs;
    ctx.context = {{2, protocol::Series::MS, protocol::Generation::V2_3}};
    const QVector<RecordEvent> records{RecordEvent::data(RecordEvent::Kind::Tx, 0, "A"),
                                       RecordEvent::data(RecordEvent::Kind::Rx, 10 * kMs, "B"), ctx,
                                       RecordEvent::data(RecordEvent::Kind::Rx, 5000 * kMs, "C"),
                                       RecordEvent::data(RecordEvent::Kind::Rx, 5010 * kMs, "D")};
    for (const RecordEvent &r : records) {
        enc.append(r);
        file += enc.takeBlock();
        if (ends)
            ends->append(file.size());
    }
    return file;
}

struct Rig {
    QTemporaryDir dir;
    std::shared_ptr<ManualClock> clock = std::make_shared<ManualClock>();
    ManualTimers timers{clock};
    std::unique_ptr<ReplayTransport> replay;
    QStringList got; ///< "<wall ms>:<bytes>"

    explicit Rig(double speed, bool fastForward = false, const QByteArray &file = recording())
    {
        const QString path = dir.filePath(QStringLiteral("r.lkrec"));
        writeFile(path, file);
        ReplayTransport::Options o;
        o.speed = speed;
        o.fastForward = fastForward;
        o.wallClock = clock;
        o.timers = timers.factory();
        replay = std::make_unique<ReplayTransport>(path, o);
        QObject::connect(replay.get(), &Transport::bytesReceived, [this](const QByteArray &b) {
            got.append(QStringLiteral("%1:%2").arg(clock->nowNs() / kMs).arg(QString(b)));
        });
    }
};

} // namespace

class tst_ReplayTransport : public QObject {
    Q_OBJECT
private slots:
    void playsAtRecordedTimesScaledBySpeed_data()
    {
        QTest::addColumn<double>("speed");
        QTest::addColumn<QStringList>("want");
        // The silences before the context (2.99 s) and before C (2 s) play as 1 s (skip idle)
        // of recording time each.
        QTest::newRow("1x") << 1.0 << QStringList{"0:A", "10:B", "2010:C", "2020:D"};
        QTest::newRow("2x") << 2.0 << QStringList{"0:A", "5:B", "1005:C", "1010:D"};
        QTest::newRow("0.25x") << 0.25 << QStringList{"0:A", "40:B", "8040:C", "8080:D"};
        // 0.5 ms steps wait a whole millisecond (the timers' resolution).
        QTest::newRow("100x clamps to 20x") << 100.0 << QStringList{"0:A", "1:B", "101:C", "102:D"};
    }
    void playsAtRecordedTimesScaledBySpeed()
    {
        QFETCH(double, speed);
        QFETCH(QStringList, want);
        Rig rig(speed);
        QSignalSpy finished(rig.replay.get(), &ReplayTransport::finished);
        QSignalSpy records(rig.replay.get(), &ReplayTransport::recordPlayed);
        QVERIFY(rig.replay->open());
        QCOMPARE(rig.replay->state(), Transport::State::Open);
        QCOMPARE(rig.replay->baud(), 115200);
        QCOMPARE(rig.replay->durationNs(), 5010 * kMs);
        rig.timers.advance(0);
        rig.timers.advance(10000);
        QCOMPARE(rig.got, want);
        QCOMPARE(finished.size(), 1);
        QCOMPARE(records.size(), 1); // the context
        QCOMPARE(rig.replay->positionNs(), 5010 * kMs);
        QCOMPARE(rig.replay->recordingClock()->nowNs(), 5010 * kMs);
    }

    void writeSendsNothingAndReports()
    {
        Rig rig(1.0);
        QVERIFY(rig.replay->open());
        QSignalSpy refused(rig.replay.get(), &ReplayTransport::writeRefused);
        rig.replay->write(QByteArray::fromHex("3e800100bf"));
        QCOMPARE(refused.size(), 1);
        QCOMPARE(refused.at(0).at(0).toInt(), 5);
        QCOMPARE(rig.replay->refusedWriteBytes(), qint64(5));
        QCOMPARE(rig.got, QStringList{}); // and nothing comes back from "the wire"
    }

    void pauseHoldsAndPlayResumes()
    {
        Rig rig(1.0);
        QVERIFY(rig.replay->open());
        rig.timers.advance(0);
        rig.replay->pause();
        rig.timers.advance(5000);
        QCOMPARE(rig.got, QStringList{"0:A"});
        rig.replay->play();
        rig.timers.advance(10);
        QCOMPARE(rig.got, (QStringList{"0:A", "5010:B"}));
    }

    void seekBringsTheContextInForce()
    {
        Rig rig(1.0);
        QSignalSpy records(rig.replay.get(), &ReplayTransport::recordPlayed);
        QVERIFY(rig.replay->open());
        QVERIFY(rig.replay->seek(4500 * kMs));
        QCOMPARE(records.size(), 1);
        const auto ctx = qvariant_cast<RecordEvent>(records.at(0).at(0));
        QCOMPARE(int(ctx.kind), int(RecordEvent::Kind::Context));
        QCOMPARE(ctx.context.value(0).id, 2);
        QVERIFY(ctx.context.value(0).series == protocol::Series::MS);
        rig.timers.advance(600);
        QCOMPARE(rig.got, (QStringList{"500:C", "510:D"}));
        // Back to the start: the header's context, then A again.
        QVERIFY(rig.replay->seek(0));
        const auto initial = qvariant_cast<RecordEvent>(records.last().at(0));
        QVERIFY(initial.context == testHeader().context);
        rig.timers.advance(0);
        QCOMPARE(rig.got.last(), QStringLiteral("600:A"));
    }

    void loadAllPlaysEverythingAtOnce()
    {
        Rig rig(1.0, true);
        QSignalSpy finished(rig.replay.get(), &ReplayTransport::finished);
        QVERIFY(rig.replay->open());
        rig.timers.advance(0);
        QCOMPARE(rig.got, (QStringList{"0:A", "0:B", "0:C", "0:D"}));
        QCOMPARE(finished.size(), 1);
    }

    void aDamagedFilePlaysToItsDamage()
    {
        QVector<qsizetype> ends;
        QByteArray file = recording(&ends);
        file[ends[2] + 22] = char(file[ends[2] + 22] ^ 1); // C's block
        Rig rig(1.0, true, file);
        QVERIFY(rig.replay->open());
        QCOMPARE(int(rig.replay->damage().kind), int(RecordingError::Kind::Damaged));
        QCOMPARE(rig.replay->damage().offset, qint64(ends[2]));
        rig.timers.advance(0);
        QCOMPARE(rig.got, (QStringList{"0:A", "0:B"}));
    }

    void aMissingFileIsAnError()
    {
        auto clock = std::make_shared<ManualClock>();
        ManualTimers timers(clock);
        ReplayTransport::Options o;
        o.wallClock = clock;
        o.timers = timers.factory();
        ReplayTransport replay(QStringLiteral("/nonexistent/x.lkrec"), o);
        QSignalSpy errors(&replay, &Transport::errorOccurred);
        QVERIFY(!replay.open());
        QCOMPARE(errors.size(), 1);
        QCOMPARE(replay.state(), Transport::State::Closed);
    }
};

QTEST_GUILESS_MAIN(tst_ReplayTransport)
#include "tst_replaytransport.moc"
