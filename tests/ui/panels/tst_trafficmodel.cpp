#include "../../support/FileSizeLimit.h"

#include <bus/MultiTorque.h>
#include <bus/TrafficRecorder.h>

#include <panels/BusModel.h>
#include <panels/TrafficFilter.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>

#include <protocol/CanRecord.h>
#include <protocol/FieldJson.h>
#include <protocol/LinkCodec.h>
#include <protocol/Reply.h>
#include <protocol/RequestBuilder.h>
#include <protocol/StreamParser.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QLabel>
#include <QtWidgets/QToolButton>

using lk::bus::TrafficBatch;
using lk::bus::TrafficEvent;
using lk::ui::TrafficModel;
namespace protocol = lk::protocol;

namespace {

/// A request as the bus thread records it: bytes, parsed frame, decode context.
TrafficEvent sent(double t, const protocol::Request &r, protocol::DecodeContext context = {})
{
    TrafficEvent e;
    e.kind = TrafficEvent::Kind::Sent;
    e.time = t;
    e.frame = r.toFrame();
    e.bytes = e.frame.encode();
    e.id = r.id;
    e.command = quint8(r.command);
    e.context = context;
    return e;
}

/// A reply as the bus thread records it, decoded with `context` (its ID's series then).
TrafficEvent received(double t, const protocol::Reply &r, protocol::DecodeContext context = {})
{
    TrafficEvent e;
    e.kind = TrafficEvent::Kind::Frame;
    e.time = t;
    e.frame = r.toFrame();
    e.bytes = e.frame.encode();
    e.id = r.id;
    e.command = quint8(r.command);
    e.context = context;
    return e;
}

TrafficEvent fault(double t, protocol::ParseError error, const QByteArray &bytes)
{
    TrafficEvent e;
    e.kind = TrafficEvent::Kind::Fault;
    e.time = t;
    e.error = error;
    e.bytes = bytes;
    return e;
}

TrafficEvent timeout(double t, int id, protocol::Command c)
{
    TrafficEvent e;
    e.kind = TrafficEvent::Kind::Timeout;
    e.time = t;
    e.id = id;
    e.command = quint8(c);
    return e;
}

protocol::Reply state2Reply(int id, qint16 speed)
{
    protocol::State2 s;
    s.temperatureC = 31;
    s.torqueRaw = 100;
    s.speedDps = speed;
    s.encoder = 1234;
    return protocol::Reply{protocol::Command::ReadState2, quint8(id), s};
}

/// A small exchange: two polls, a speed command, a timeout and a corrupt frame.
TrafficBatch sampleTraffic()
{
    TrafficBatch b;
    b << sent(0.001, *protocol::build::plain(protocol::Command::ReadState2, 1).request)
      << received(0.002, state2Reply(1, 360))
      << sent(0.003, *protocol::build::speed(2, 100.0).request)
      << received(0.004, state2Reply(2, 100))
      << sent(0.005, *protocol::build::plain(protocol::Command::ReadState1, 3).request)
      << timeout(0.010, 3, protocol::Command::ReadState1);
    QByteArray bad = state2Reply(1, 7).encode();
    bad[bad.size() - 1] = char(bad.at(bad.size() - 1) ^ 0x55); // data checksum broken
    b << fault(0.011, protocol::ParseError::BadDataChecksum, bad);
    return b;
}

/// Bytes of a text export, read the way `lkctl decode -` does: hex pairs, '#' comments.
QByteArray hexOf(const QString &text)
{
    QByteArray out;
    const auto lines = text.split(QLatin1Char('\n'));
    for (QString line : lines) {
        const int hash = line.indexOf(QLatin1Char('#'));
        if (hash >= 0)
            line.truncate(hash);
        out += QByteArray::fromHex(line.remove(QLatin1Char(' ')).toLatin1());
    }
    return out;
}

protocol::DecodeContext onCan()
{
    protocol::DecodeContext c;
    c.link = protocol::Link::Can;
    return c;
}

/// A request as the bus thread records it on CAN: one CanRecord, frame and context.
TrafficEvent sentOnCan(double t, const protocol::Request &r)
{
    TrafficEvent e = sent(t, r, onCan());
    e.bytes = protocol::encodeRequest(r, onCan()).bytes;
    return e;
}

/// A reply as received on CAN, stamped by the adapter at `adapterUs`.
TrafficEvent receivedOnCan(double t, const protocol::Reply &r, qint64 adapterUs)
{
    TrafficEvent e = received(t, r, onCan());
    protocol::CanRecord record =
        *protocol::CanRecord::decode(protocol::encodeReply(r, onCan()).bytes);
    record.timestampUs = adapterUs;
    e.bytes = record.encode();
    return e;
}

} // namespace

class tst_TrafficModel : public QObject {
    Q_OBJECT
private slots:
    void columns();
    void boundedRing_data();
    void boundedRing();
    void countsFaultsByKind();
    void filterByIdAndCommand_data();
    void filterByIdAndCommand();
    void exportParsesBack();
    void failedExportKeepsTheEarlierFile();
    void pauseKeepsCounting();
    void hiddenBacklogCountsWhatItDrops();
    void rowsDroppedElsewhereAreCounted();
    void countsAreTheBusStatistics();
    void exportReadByLkctl();
    void rowKeepsTheContextOfItsMoment();
    void fieldsComeFromTheCarriedFrame();
    void canRowsInCandumpNotation();
    void canFaultFollowsTheLink();
    void candumpLogExport();
    void multiTorqueFrameIsDecoded();
};

void tst_TrafficModel::columns()
{
    TrafficModel m;
    m.append(sampleTraffic());
    QCOMPARE(m.rowCount(), 7);
    QCOMPARE(m.data(m.index(0, TrafficModel::Command)).toString(), QStringLiteral("read_state2"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Direction)).toString(), QStringLiteral("TX"));
    QCOMPARE(m.data(m.index(1, TrafficModel::Direction)).toString(), QStringLiteral("RX"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Raw)).toString(), QStringLiteral("3E 9C 01 00 DB"));
    QVERIFY(m.data(m.index(1, TrafficModel::Fields)).toString().contains(QStringLiteral("360")));
    QVERIFY(m.data(m.index(2, TrafficModel::Fields)).toString().contains(QStringLiteral("100")));
    QCOMPARE(m.data(m.index(2, TrafficModel::Id)).toInt(), 2);
    QCOMPARE(m.data(m.index(5, TrafficModel::Direction)).toString(), QStringLiteral("timeout"));
    QCOMPARE(m.data(m.index(6, TrafficModel::Command)).toString(),
             QStringLiteral("bad_data_checksum"));
}

void tst_TrafficModel::boundedRing_data()
{
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("batches");
    QTest::newRow("fits") << 100 << 10;
    QTest::newRow("wraps") << 20 << 10;
    QTest::newRow("one batch larger than the ring") << 5 << 1;
}

void tst_TrafficModel::boundedRing()
{
    QFETCH(int, capacity);
    QFETCH(int, batches);
    TrafficModel m(nullptr, capacity);
    int total = 0;
    for (int b = 0; b < batches; ++b) {
        TrafficBatch batch = sampleTraffic();
        for (auto &e : batch)
            e.time += b;
        m.append(batch);
        total += batch.size();
    }
    QCOMPARE(m.rowCount(), qMin(capacity, total));
    QCOMPARE(qint64(m.droppedRows()), qint64(total - m.rowCount()));
    // The newest event is always the last row.
    QCOMPARE(m.event(m.rowCount() - 1).time, 0.011 + batches - 1);
    QCOMPARE(m.counts().sent, quint64(3 * batches)); // counted even when dropped
}

void tst_TrafficModel::countsFaultsByKind()
{
    TrafficModel m;
    m.append(sampleTraffic());
    m.append({fault(1, protocol::ParseError::Garbage, QByteArray("\x01\x02", 2))});
    const auto &c = m.counts();
    QCOMPARE(c.timeouts, quint64(1));
    QCOMPARE(c.faults[size_t(protocol::ParseError::BadDataChecksum)], quint64(1));
    QCOMPARE(c.faults[size_t(protocol::ParseError::Garbage)], quint64(1));
    QCOMPARE(c.faultTotal(), quint64(2));
    QCOMPARE(c.frames, quint64(2));
}

void tst_TrafficModel::filterByIdAndCommand_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<int>("command");
    QTest::addColumn<bool>("faultsOnly");
    QTest::addColumn<int>("rows");
    QTest::newRow("all") << 0 << -1 << false << 7;
    QTest::newRow("id 1") << 1 << -1 << false << 2;
    QTest::newRow("id 3") << 3 << -1 << false << 2;
    QTest::newRow("speed") << 0 << int(protocol::Command::Speed) << false << 1;
    QTest::newRow("read_state2") << 0 << int(protocol::Command::ReadState2) << false << 3;
    QTest::newRow("id 2, read_state2") << 2 << int(protocol::Command::ReadState2) << false << 1;
    QTest::newRow("faults") << 0 << -1 << true << 2;
}

void tst_TrafficModel::filterByIdAndCommand()
{
    QFETCH(int, id);
    QFETCH(int, command);
    QFETCH(bool, faultsOnly);
    QFETCH(int, rows);
    TrafficModel m;
    lk::ui::TrafficFilter f;
    f.setSourceModel(&m);
    m.append(sampleTraffic());
    f.setIdFilter(id);
    f.setCommandFilter(command);
    f.setFaultsOnly(faultsOnly);
    QCOMPARE(f.rowCount(), rows);
    m.append(sampleTraffic()); // new rows go through the same filter
    QCOMPARE(f.rowCount(), 2 * rows);
}

void tst_TrafficModel::exportParsesBack()
{
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus);
    const TrafficBatch traffic = sampleTraffic();
    panel.appendTraffic(traffic);
    panel.flush();
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("traffic.txt"));
    QString error;
    QVERIFY2(panel.exportTo(file, &error), qPrintable(error));
    QFile in(file);
    QVERIFY(in.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(in.readAll());

    // Every byte on the wire comes back, in order, and parses to the same frames and faults.
    QByteArray expected;
    for (const auto &e : traffic)
        expected += e.bytes;
    const QByteArray bytes = hexOf(text);
    QCOMPARE(bytes, expected);
    int frames = 0;
    int faults = 0;
    protocol::StreamParser parser;
    auto sink = [&](const protocol::ParseEvent &e) { (e.isFrame ? frames : faults)++; };
    parser.feed(bytes, sink);
    parser.finish(sink);
    QCOMPARE(frames, 5); // three requests, two replies
    QCOMPARE(faults, 1);
    QVERIFY(text.contains(QStringLiteral("# 0.010000 timeout id 3 read_state1")));

    // The export follows the filter: only ID 2's rows.
    panel.filter()->setIdFilter(2);
    QVERIFY(panel.exportTo(file, &error));
    QVERIFY(in.seek(0));
    in.close();
    QVERIFY(in.open(QIODevice::ReadOnly | QIODevice::Text));
    QCOMPARE(hexOf(QString::fromUtf8(in.readAll())), traffic[2].bytes + traffic[3].bytes);
}

void tst_TrafficModel::failedExportKeepsTheEarlierFile()
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("traffic.txt"));
    const QByteArray earlier("# an earlier export\n");
    {
        QFile out(file);
        QVERIFY(out.open(QIODevice::WriteOnly));
        QCOMPARE(out.write(earlier), earlier.size());
    }
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus);
    panel.appendTraffic(sampleTraffic());
    panel.flush();
    QString error;
    {
        // The disk fills up halfway: the new log is longer than the earlier one.
        const lk::testsupport::FileSizeLimit diskFull(earlier.size());
        QVERIFY(diskFull.isActive());
        QVERIFY(!panel.exportTo(file, &error));
    }
    QVERIFY2(error.contains(file), qPrintable(error));
    QFile in(file);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QCOMPARE(in.readAll(), earlier);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
             QStringList{QStringLiteral("traffic.txt")}); // no half-written copy beside it
}

void tst_TrafficModel::hiddenBacklogCountsWhatItDrops()
{
    // A hidden table is not filled: its backlog keeps whole batches as long as the table could
    // keep one of their rows, and counts the rest as rows dropped (a replay's Load all).
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus, nullptr, 10);
    QVERIFY(!panel.wantsCapture());
    for (int i = 0; i < 6; ++i)
        panel.appendTraffic(sampleTraffic()); // 42 rows of 7
    QCOMPARE(panel.trafficModel()->rowCount(), 0);
    panel.flush();
    QCOMPARE(panel.trafficModel()->rowCount(), 10);
    QCOMPARE(panel.trafficModel()->droppedRows(), quint64(32));
    QCOMPARE(panel.trafficModel()->counts().timeouts, quint64(6)); // every batch counted
}

void tst_TrafficModel::rowsDroppedElsewhereAreCounted()
{
    // A replay's Load all hands on only the rows the table keeps and the counts of the rest:
    // they reach the summary and the dropped total with the next flush, beside the rows.
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus, nullptr, 10);
    lk::bus::TrafficCounts elsewhere;
    for (int i = 0; i < 3; ++i)
        elsewhere.add(sampleTraffic()); // 21 rows, 3 timeouts
    panel.countDroppedTraffic(elsewhere);
    panel.appendTraffic(sampleTraffic());
    panel.flush();
    QCOMPARE(panel.trafficModel()->rowCount(), 7);
    QCOMPARE(panel.trafficModel()->droppedRows(), quint64(21));
    QCOMPARE(panel.trafficModel()->counts().timeouts, quint64(4));
    QVERIFY(panel.countsText().contains(QStringLiteral("bad_data_checksum 4")));
    // Counts alone are flushed too.
    panel.countDroppedTraffic(elsewhere);
    panel.flush();
    QCOMPARE(panel.trafficModel()->droppedRows(), quint64(42));
    QCOMPARE(panel.trafficModel()->rowCount(), 7);
}

void tst_TrafficModel::pauseKeepsCounting()
{
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus);
    auto *pause = panel.findChild<QToolButton *>(QStringLiteral("trafficPause"));
    QVERIFY(pause);
    panel.appendTraffic(sampleTraffic());
    panel.flush();
    QCOMPARE(panel.trafficModel()->rowCount(), 7);
    QTest::mouseClick(pause, Qt::LeftButton);
    QVERIFY(panel.isPaused());
    panel.appendTraffic(sampleTraffic());
    panel.flush();
    QCOMPARE(panel.trafficModel()->rowCount(), 7); // frozen
    QCOMPARE(panel.trafficModel()->counts().timeouts, quint64(2));
    QVERIFY(panel.countsText().contains(QStringLiteral("bad_data_checksum 2")));
}

void tst_TrafficModel::countsAreTheBusStatistics()
{
    // The counts line shows the bus's counters (what the Dashboard and the status bar show),
    // whatever the log holds; the log adds its faults by kind.
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus);
    panel.appendTraffic(sampleTraffic());
    panel.flush();
    lk::bus::BusStatistics st;
    st.bus.requests = 120;
    st.bus.replies = 117;
    st.bus.timeouts = 3;
    st.bus.checksumErrors = 1;
    st.bus.lateReplies = 2;
    bus.setStatistics(st);
    const QString text = panel.countsText();
    QVERIFY2(text.contains(QStringLiteral("TX 120")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("RX 117")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("timeouts 3")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("checksum errors 1")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("late replies 2")), qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("unexpected")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("bad_data_checksum 1")), qPrintable(text));
    auto *counts = panel.findChild<QLabel *>(QStringLiteral("trafficCounts"));
    QVERIFY(counts);
    QCOMPARE(counts->text(), text); // updated as the statistics arrive

    // Closing the link clears the statistics: the counts follow.
    bus.setStatistics({});
    QVERIFY2(panel.countsText().contains(QStringLiteral("TX 0")), qPrintable(panel.countsText()));
    QCOMPARE(counts->text(), panel.countsText());
}

void tst_TrafficModel::exportReadByLkctl()
{
    const QString lkctl =
        qEnvironmentVariable("LK_TEST_BINARY_DIR") + QStringLiteral("/app/lkctl/lkctl");
    if (!QFileInfo::exists(lkctl))
        QSKIP("lkctl is not built in this tree");
    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus);
    panel.appendTraffic(sampleTraffic());
    panel.flush();
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("traffic.txt"));
    QVERIFY(panel.exportTo(file));
    QProcess p;
    p.setStandardInputFile(file);
    p.start(lkctl, {QStringLiteral("decode"), QStringLiteral("-")});
    QVERIFY(p.waitForFinished(30000));
    const QList<QByteArray> lines = p.readAllStandardOutput().trimmed().split('\n');
    QCOMPARE(p.exitCode(), 3); // the corrupt frame is reported, as on the bus
    QCOMPARE(lines.size(), 6);
    QVERIFY(lines[0].contains("\"command\":\"read_state2\""));
    QVERIFY(lines[2].contains("\"speed_dps\":100"));
    QVERIFY(lines[5].contains("bad_data_checksum"));
}

void tst_TrafficModel::rowKeepsTheContextOfItsMoment()
{
    // ID 5 replied while it was taken for an MF drive (iq), then was learnt to be an MS
    // (power): the earlier row still reads as it was decoded then, in the view and the export.
    protocol::DecodeContext mf;
    mf.series = protocol::Series::MF;
    protocol::DecodeContext ms;
    ms.series = protocol::Series::MS;
    TrafficModel m;
    m.append({received(0.1, state2Reply(5, 360), mf)});
    const QString before = m.data(m.index(0, TrafficModel::Fields)).toString();
    QVERIFY2(before.contains(QStringLiteral("iq")), qPrintable(before));
    const QString exportBefore = m.exportLine(0);
    m.append({received(0.2, state2Reply(5, 360), ms)});
    QCOMPARE(m.data(m.index(0, TrafficModel::Fields)).toString(), before);
    QCOMPARE(m.exportLine(0), exportBefore);
    const QString after = m.data(m.index(1, TrafficModel::Fields)).toString();
    QVERIFY2(after.contains(QStringLiteral("power")), qPrintable(after));
    QVERIFY(!after.contains(QStringLiteral("iq")));
}

void tst_TrafficModel::fieldsComeFromTheCarriedFrame()
{
    // The model formats the frame the bus thread parsed and never parses `bytes` itself
    // (TrafficModel includes no parser): bytes that hold no frame still show the carried
    // frame's fields, while the hex column keeps the bytes as they were.
    TrafficEvent e = sent(0.1, *protocol::build::speed(2, 100.0).request);
    e.bytes = QByteArray("\x01\x02\x03", 3);
    TrafficModel m;
    m.append({e});
    const QString fields = m.data(m.index(0, TrafficModel::Fields)).toString();
    QVERIFY2(fields.contains(QStringLiteral("100")), qPrintable(fields));
    QCOMPARE(m.data(m.index(0, TrafficModel::Raw)).toString(), QStringLiteral("01 02 03"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Fields)).toString(), fields); // the cached text
    QCOMPARE(m.fieldsText(0), fields);
}

void tst_TrafficModel::canRowsInCandumpNotation()
{
    // CAN.md section 9: read state 2 of drive 1 is 141#9C00000000000000.
    TrafficModel m;
    m.append({sentOnCan(0.001, *protocol::build::plain(protocol::Command::ReadState2, 1).request),
              receivedOnCan(0.002, state2Reply(1, 360), 1700000000123456),
              sent(0.003, *protocol::build::plain(protocol::Command::ReadState2, 1).request)});
    QCOMPARE(m.data(m.index(0, TrafficModel::Raw)).toString(),
             QStringLiteral("141#9C00000000000000"));
    const QString reply = m.data(m.index(1, TrafficModel::Raw)).toString();
    QVERIFY2(reply.startsWith(QStringLiteral("141#9C1F6400")), qPrintable(reply));
    QVERIFY(m.exportLine(0).startsWith(QStringLiteral("141#9C00000000000000  # ")));
    // An RS485 row (its own context says so) keeps its hex bytes.
    QCOMPARE(m.data(m.index(2, TrafficModel::Raw)).toString(),
             protocol::FieldJson::hexText(
                 protocol::build::plain(protocol::Command::ReadState2, 1).request->encode()));
}

void tst_TrafficModel::canFaultFollowsTheLink()
{
    // A fault carries no decode context: the connection's link says how its bytes read.
    protocol::CanRecord r;
    r.canId = 0x145;
    r.data = QByteArray::fromHex("9C01");
    TrafficModel m;
    m.append({fault(0.1, protocol::ParseError::BadLength, r.encode())});
    QVERIFY(m.data(m.index(0, TrafficModel::Raw)).toString().contains(QLatin1Char(' ')));
    m.setLink(protocol::Link::Can);
    QCOMPARE(m.data(m.index(0, TrafficModel::Raw)).toString(), QStringLiteral("145#9C01"));
    // Bytes that are no whole record stay hex.
    m.append({fault(0.2, protocol::ParseError::Truncated, QByteArray("\x01\x02", 2))});
    QCOMPARE(m.data(m.index(1, TrafficModel::Raw)).toString(), QStringLiteral("01 02"));
}

void tst_TrafficModel::candumpLogExport()
{
    lk::ui::BusModel bus;
    bus.setLink(protocol::Link::Can, QStringLiteral("tcp://127.0.0.1:35468/can1"));
    lk::ui::TrafficPanel panel(&bus);
    panel.appendTraffic(
        {sentOnCan(1.5, *protocol::build::plain(protocol::Command::ReadState2, 1).request),
         receivedOnCan(1.500625, state2Reply(1, 360), 1700000000123456),
         timeout(2.0, 3, protocol::Command::ReadState1)});
    panel.flush();
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("traffic.log"));
    QVERIFY(panel.exportCandumpTo(file));
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2); // frames only: a timeout is no frame on the wire
    // One clock, the session's, for sent and received alike.
    QCOMPARE(lines[0], QStringLiteral("(1.500000) can1 141#9C00000000000000"));
    QVERIFY2(lines[1].startsWith(QStringLiteral("(1.500625) can1 141#9C")), qPrintable(lines[1]));
    for (const QString &line : lines) // what can-utils' candump -L writes, read back
        QVERIFY2(protocol::CanRecord::fromCandump(line).has_value(), qPrintable(line));
}

void tst_TrafficModel::multiTorqueFrameIsDecoded()
{
    // Our own 0x280 as the bus thread records it (CAN.md section 4.2): one record on no
    // drive's ID, so its frame is empty; the row reads it from the bytes, every slot named.
    protocol::DecodeContext oldCan = onCan();
    oldCan.series = protocol::Series::MG;
    const QByteArray bytes =
        lk::bus::encodeMultiTorque({*protocol::build::torque(1, 1.6, oldCan).request,
                                    *protocol::build::torque(2, -1.6, oldCan).request});
    lk::bus::TrafficRecorder recorder;
    recorder.setEnabled(true);
    recorder.recordSent(0.25, bytes, oldCan);
    TrafficModel m;
    m.append(recorder.take(0.25));
    QCOMPARE(m.rowCount(), 1);
    QCOMPARE(m.data(m.index(0, TrafficModel::Raw)).toString(),
             QStringLiteral("280#64009CFF00000000"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Command)).toString(), QStringLiteral("multi_torque"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Command), Qt::ToolTipRole).toString(),
             QStringLiteral("Multi-motor torque (0x280)"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Fields)).toString(),
             QStringLiteral("torque current of IDs 1..4: ID 1 1.60 A, ID 2 -1.60 A, ID 3 0.00 A, "
                            "ID 4 0.00 A"));
    QCOMPARE(m.data(m.index(0, TrafficModel::Id)), QVariant()); // no one drive's
    // The command filter's torque shows it with the replies it draws.
    QCOMPARE(m.data(m.index(0, 0), TrafficModel::kCommandRole).toInt(),
             int(protocol::Command::Torque));
    QCOMPARE(m.exportLine(0), QStringLiteral("280#64009CFF00000000  # 0.250000 TX multi_torque: "
                                             "torque current of IDs 1..4: ID 1 1.60 A, ID 2 "
                                             "-1.60 A, ID 3 0.00 A, ID 4 0.00 A"));
    // The same bytes from an RS485 context are no CAN record: not decoded as one.
    TrafficEvent rs485 = m.event(0);
    rs485.context = {};
    m.append({rs485});
    QVERIFY(m.commandText(1) != QLatin1String("multi_torque"));
}

QTEST_MAIN(tst_TrafficModel)
#include "tst_trafficmodel.moc"
