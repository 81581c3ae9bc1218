// Reading a recording ahead on a thread of its own (Load all): the same records in the same
// order as the plain reader, none lost or doubled when it stops half-way, and a replay that
// switches it on and off, or seeks while it runs, plays what it plays without it.
#include "RecordingTestUtil.h"

#include "../support/ManualTimers.h"

#include <recording/RecordFile.h>
#include <recording/RecordReadAhead.h>
#include <recording/ReplayTransport.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace lk::recording;
using lk::testsupport::ManualClock;
using lk::testsupport::ManualTimers;
using lk::testsupport::testHeader;

namespace {

// Several read-ahead chunks and more than it keeps ready at once.
constexpr int kRecords = RecordReadAhead::kChunkRecords * (RecordReadAhead::kChunksAhead + 5) + 7;

/// kRecords chunks "r<i>", 100 us apart, in blocks of 500, with a context record every 3000.
bool writeRecording(const QString &path)
{
    RecordFile file;
    if (file.create(path) || file.write(RecordEncoder::encodeHeader(testHeader())))
        return false;
    RecordEncoder enc;
    for (int i = 0; i < kRecords; ++i) {
        const qint64 t = qint64(i) * 100'000;
        if (i % 3000 == 2999) {
            RecordEvent ctx;
            ctx.kind = RecordEvent::Kind::Context;
            ctx.timeNs = t;
            ctx.context = {{i % 32 + 1, lk::protocol::Series::MG, lk::protocol::Generation::V2_3}};
            enc.append(ctx);
        }
        enc.append(RecordEvent::data(i % 2 ? RecordEvent::Kind::Rx : RecordEvent::Kind::Tx, t,
                                     QByteArray("r") + QByteArray::number(i)));
        if (i % 500 == 499 && file.write(enc.takeBlock()))
            return false;
    }
    const bool ok = !file.write(enc.takeBlock());
    file.close();
    return ok;
}

QString describe(const RecordEvent &e)
{
    if (e.kind == RecordEvent::Kind::Context)
        return QStringLiteral("ctx@%1").arg(e.timeNs);
    return QStringLiteral("%1@%2").arg(QString::fromLatin1(e.bytes)).arg(e.timeNs);
}

QStringList plain(const QString &path, RecordingError *error = nullptr)
{
    QStringList out;
    for (const RecordEvent &e : lk::testsupport::readAll(path, error))
        out << describe(e);
    return out;
}

/// Every record of `path` through a RecordReadAhead run to its end; `error` gets the reader's,
/// `leftOver` whether stop() still held records (it must not, after the end).
QStringList readAhead(const QString &path, RecordingError *error, bool *leftOver)
{
    RecordingReader reader;
    QStringList got;
    if (!reader.open(path))
        return got;
    RecordReadAhead ahead(reader);
    ahead.start();
    RecordEvent e;
    while (ahead.next(&e))
        got << describe(e);
    *leftOver = !ahead.stop().empty();
    *error = reader.error();
    return got;
}

/// The chunks a replay plays, in order.
struct Played {
    QStringList chunks;
    void connectTo(ReplayTransport &replay)
    {
        replay.setChunkHandler(
            [this](const QByteArray &b, bool) { chunks << QString::fromLatin1(b); });
    }
};

} // namespace

class tst_RecordReadAhead : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_path = m_dir.filePath(QStringLiteral("many.lkrec"));
        QVERIFY(writeRecording(m_path));
        m_plain = plain(m_path);
        QVERIFY(m_plain.size() > kRecords);
    }

    void readsWhatThePlainReaderReads()
    {
        RecordingError error;
        bool leftOver = true;
        QCOMPARE(readAhead(m_path, &error, &leftOver), m_plain);
        QVERIFY(!leftOver);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::None));
    }

    void stoppingHalfWayLosesAndDoublesNothing_data()
    {
        QTest::addColumn<int>("taken");
        QTest::newRow("none") << 0;
        QTest::newRow("within the first chunk") << 10;
        QTest::newRow("a chunk's end") << RecordReadAhead::kChunkRecords;
        QTest::newRow("many chunks in") << RecordReadAhead::kChunkRecords * 5 + 3;
    }

    void stoppingHalfWayLosesAndDoublesNothing()
    {
        QFETCH(int, taken);
        RecordingReader reader;
        QVERIFY(reader.open(m_path));
        RecordReadAhead ahead(reader);
        ahead.start();
        QStringList got;
        RecordEvent e;
        for (int i = 0; i < taken && ahead.next(&e); ++i)
            got << describe(e);
        // What it read and nobody took, then the reader from where it stopped.
        for (const RecordEvent &left : ahead.stop())
            got << describe(left);
        while (reader.next(&e))
            got << describe(e);
        QCOMPARE(got, m_plain);
        // Started again on the same reader, it goes on from there.
        ahead.start();
        QVERIFY(!ahead.next(&e));
        QVERIFY(ahead.stop().empty());
    }

    void stopsAtDamageAsThePlainReaderDoes()
    {
        // A flipped byte in the tenth block: the records before it, then the reader's error.
        QFile in(m_path);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray bytes = in.readAll();
        RecordingReader probe;
        QVERIFY(probe.open(m_path));
        const QVector<RecordingReader::Block> blocks = probe.index();
        QVERIFY(blocks.size() > 10);
        bytes[qsizetype(blocks[10].offset) + 20] =
            char(bytes[qsizetype(blocks[10].offset) + 20] ^ 1);
        const QString damaged = m_dir.filePath(QStringLiteral("damaged.lkrec"));
        QVERIFY(lk::testsupport::writeFile(damaged, bytes));
        RecordingError plainError;
        const QStringList expected = plain(damaged, &plainError);
        QCOMPARE(int(plainError.kind), int(RecordingError::Kind::Damaged));
        RecordingError error;
        bool leftOver = true;
        QCOMPARE(readAhead(damaged, &error, &leftOver), expected);
        QVERIFY(!leftOver);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::Damaged));
        QCOMPARE(error.offset, plainError.offset);
    }

    void aReplayPlaysTheSameWithAndWithoutIt()
    {
        Played without;
        Played with;
        for (Played *played : {&without, &with}) {
            ReplayTransport replay(m_path, options());
            played->connectTo(replay);
            QVERIFY(replay.open());
            replay.pause();
            int batches = 0;
            if (played == &with)
                replay.setReadAhead(true);
            while (replay.playNextBatch()) {
                // Off and on again between batches, as pause and Load all again do.
                if (played == &with && ++batches % 3 == 0) {
                    replay.setReadAhead(false);
                    replay.setReadAhead(true);
                }
            }
            replay.setReadAhead(false);
            QVERIFY(replay.isFinished());
        }
        QCOMPARE(with.chunks.size(), kRecords);
        QCOMPARE(with.chunks, without.chunks);
    }

    void aSeekWhileItRunsStartsFromThere()
    {
        ReplayTransport replay(m_path, options());
        Played played;
        played.connectTo(replay);
        QVERIFY(replay.open());
        replay.pause();
        replay.setReadAhead(true);
        QVERIFY(replay.playNextBatch());
        const qint64 at = qint64(kRecords - 100) * 100'000; // near the end: far ahead of it
        QVERIFY(replay.seek(at));
        played.chunks.clear();
        while (replay.playNextBatch()) {
        }
        QCOMPARE(played.chunks.size(), 100);
        QCOMPARE(played.chunks.first(), QStringLiteral("r%1").arg(kRecords - 100));
        QCOMPARE(played.chunks.last(), QStringLiteral("r%1").arg(kRecords - 1));
    }

    void closingWhileItRunsStopsIt()
    {
        auto replay = std::make_unique<ReplayTransport>(m_path, options());
        QVERIFY(replay->open());
        replay->pause();
        replay->setReadAhead(true);
        QVERIFY(replay->playNextBatch());
        replay->close(); // joins the reading thread; nothing left running after the delete
        QVERIFY(replay->isFinished());
        replay.reset();
    }

private:
    ReplayTransport::Options options()
    {
        ReplayTransport::Options o;
        o.wallClock = m_clock;
        o.timers = m_timers.factory();
        return o;
    }

    QTemporaryDir m_dir;
    QString m_path;
    QStringList m_plain;
    std::shared_ptr<ManualClock> m_clock = std::make_shared<ManualClock>();
    ManualTimers m_timers{m_clock};
};

QTEST_GUILESS_MAIN(tst_RecordReadAhead)
#include "tst_recordreadahead.moc"
