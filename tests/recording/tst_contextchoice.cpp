// The user's choice of a drive's series and generation in a recording (docs/RECORDING.md
// "Context"): recorded when the session learns it (KnownMotor::identityChosen), read back,
// written so that a context without a choice keeps its earlier bytes, and kept on replay
// against a reply's hint as the live session keeps it.
#include "RecordingTestUtil.h"

#include <protocol/CanRecord.h>
#include <recording/Crc32.h>
#include <recording/KnownMotorsContext.h>
#include <recording/RecordedFrameParser.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace lk;
using namespace lk::recording;
using lk::testsupport::readAll;
using lk::testsupport::testHeader;
using lk::testsupport::writeFile;

namespace {

RecordEvent contextAt(qint64 timeNs, const ContextSnapshot &context)
{
    RecordEvent e;
    e.kind = RecordEvent::Kind::Context;
    e.timeNs = timeNs;
    e.context = context;
    return e;
}

/// The frame a CAN recording replays `hex` on `canId` as, its context told as replay tells it.
protocol::DecodeContext replayedContext(const ContextSnapshot &context, quint32 canId,
                                        const char *hex)
{
    RecordedFrameParser parser(context, protocol::Link::Can);
    protocol::DecodeContext got;
    const RecordEvent rx =
        RecordEvent::data(RecordEvent::Kind::Rx, 1000,
                          protocol::CanRecord::of({canId, QByteArray::fromHex(hex)}).encode());
    parser.feed(rx, [&got](const RecordedFrame &f) { got = f.context; });
    return got;
}

} // namespace

class tst_ContextChoice : public QObject {
    Q_OBJECT
private slots:
    void theSessionsChoiceIsMarked()
    {
        bus::KnownMotors motors;
        motors[1].id = 1;
        motors[1].series = protocol::Series::MG;
        motors[1].generation = protocol::Generation::V2_35;
        motors[1].identityChosen = true; // BusSession::setDriveIdentity
        motors[2].id = 2;                // seen answering, nothing chosen
        const RecordEvent e = contextRecord(42, motors);
        QCOMPARE(e.context.size(), 2);
        QVERIFY(e.context[0].chosen);
        QVERIFY(!e.context[1].chosen);
    }

    void aContextWithoutAChoiceKeepsItsBytes()
    {
        const ContextSnapshot plain{{1, protocol::Series::MS, protocol::Generation::V2_35},
                                    {7, std::nullopt, protocol::Generation::V2_3}};
        QByteArray bytes;
        RecordEncoder::putContext(bytes, plain);
        QCOMPARE(bytes.toHex(' '), QByteArray("02 01 01 01 07 00 00"));
        ContextSnapshot chosen = plain;
        chosen[1].chosen = true;
        bytes.clear();
        RecordEncoder::putContext(bytes, chosen);
        // The same entries, then the list of chosen IDs: one, drive 7.
        QCOMPARE(bytes.toHex(' '), QByteArray("02 01 01 01 07 00 00 01 07"));
    }

    void theChoiceRoundTripsInHeaderAndRecords()
    {
        RecordingHeader h = testHeader();
        h.context = {{1, protocol::Series::MS, protocol::Generation::V2_35, true}};
        const ContextSnapshot later{{1, protocol::Series::MS, protocol::Generation::V2_35, true},
                                    {4, protocol::Series::MF, protocol::Generation::V2_3, false},
                                    {9, std::nullopt, protocol::Generation::V2_35, true}};
        RecordEncoder enc;
        enc.append(contextAt(5'000, later));
        enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 6'000, QByteArray("ab")));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("c.lkrec"));
        QVERIFY(writeFile(path, RecordEncoder::encodeHeader(h) + enc.takeBlock()));
        RecordingError error;
        RecordingHeader header;
        const QVector<RecordEvent> got = readAll(path, &error, &header);
        QVERIFY2(!error.isError(), qPrintable(error.message));
        QVERIFY(header.context == h.context);
        QCOMPARE(got.size(), 2);
        QVERIFY(got[0].context == later);
        QCOMPARE(got[1].bytes, QByteArray("ab")); // the record after it still reads
    }

    void aChosenIdOutsideTheEntriesIsDamage()
    {
        RecordingHeader h = testHeader();
        h.context.clear();
        RecordEncoder enc;
        enc.append(contextAt(1, {{1, protocol::Series::MS, protocol::Generation::V2_3, true}}));
        QByteArray block = enc.takeBlock();
        // The record ends "01 01": one chosen drive, drive 1. Make it drive 5, which is none
        // of the entries, and sign the block again: only the layout is wrong.
        QVERIFY(block.endsWith(QByteArray::fromHex("0101")));
        block[block.size() - 1] = 5;
        quint32 crc = crc32(block.constData() + 4, 12);
        crc = crc32(block.constData() + kBlockHeaderSize, block.size() - kBlockHeaderSize, crc);
        for (int i = 0; i < 4; ++i)
            block[16 + i] = char(quint8(crc >> (8 * i)));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("d.lkrec"));
        QVERIFY(writeFile(path, RecordEncoder::encodeHeader(h) + block));
        RecordingError error;
        readAll(path, &error);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::Damaged));
        QVERIFY2(error.message.contains(QStringLiteral("layout")), qPrintable(error.message));
    }

    void aChosenGenerationIsNotOverriddenByAReplysHint()
    {
        // Drive 1 answers on 0x141 with the old generation's 0x9A layout (24.0 V in 0.1 V):
        // a hint that it is old. The user chose V2.36 for it (a V2.36 drive answering on
        // 0x140+ID, as hardware does): live, the choice stands, and so on replay.
        const char *oldLayout = "9A1E00F000000000";
        ContextSnapshot chosen{{1, protocol::Series::MF, protocol::Generation::V2_35, true}};
        QCOMPARE(replayedContext(chosen, 0x141, oldLayout).generation, protocol::Generation::V2_35);
        ContextSnapshot learnt{{1, protocol::Series::MF, protocol::Generation::V2_35, false}};
        QCOMPARE(replayedContext(learnt, 0x141, oldLayout).generation, protocol::Generation::V2_3);
    }
};

QTEST_APPLESS_MAIN(tst_ContextChoice)
#include "tst_contextchoice.moc"
