// A live session recorded through recordingFactory, then replayed: the replay's frames,
// decoded with the recorded context, give the same samples the live session had.
#include "../bus/BusTestUtil.h"
#include "RecordingTestUtil.h"

#include <bus/BusSession.h>
#include <record/TelemetryColumns.h>
#include <recording/KnownMotorsContext.h>
#include <recording/RecordedFrameParser.h>
#include <recording/RecordingTransport.h>
#include <recording/ReplayTransport.h>
#include <recording/SessionRecorder.h>
#include <sim/SimBus.h>
#include <transport/SimTransport.h>

#include <QtCore/QDeadlineTimer>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <cmath>

#include "../support/SampleValues.h"

using namespace lk;
using namespace lk::recording;
using bus::TelemetrySample;

namespace {

using Values = lk::testsupport::SampleValues;

Values valuesOf(const TelemetrySample &s)
{
    return lk::testsupport::sampleValuesOf(s);
}

bus::TransportFactory simFactory()
{
    return [](int baud) -> std::unique_ptr<transport::Transport> {
        auto simBus =
            sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("3:MF,17:MS,32:MG")));
        auto t = std::make_unique<transport::SimTransport>(std::move(simBus));
        t->setBaud(baud);
        return t;
    };
}

/// Drives on CAN in-process (SimTransport over SimCanFront): 1 an old CAN MG answering on
/// 0x141, 2 a V2.36 MF answering on 0x182.
bus::TransportFactory canSimFactory()
{
    return [](int bitRate) -> std::unique_ptr<transport::Transport> {
        auto simBus =
            sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("1:MG,2:MF@2.35")));
        auto t = std::make_unique<transport::SimTransport>(std::move(simBus));
        t->setLink(protocol::Link::Can);
        t->setBaud(bitRate);
        return t;
    };
}

/// The replies of a recording file as samples, parsed as its header's link says.
QVector<Values> decodedReplies(const QString &path)
{
    RecordingHeader header;
    const QVector<RecordEvent> records = lk::testsupport::readAll(path, nullptr, &header);
    RecordedFrameParser parser(header.context, linkOf(header));
    QVector<Values> out;
    const auto sink = [&](const RecordedFrame &f) {
        if (f.transmitted || !f.event.isFrame ||
            f.event.direction != protocol::FrameDirection::Reply)
            return;
        const auto reply = protocol::decodeReply(f.event.frame, f.context);
        if (const auto s = reply.reply ? TelemetrySample::fromReply(*reply.reply, 0) : std::nullopt)
            out.append(valuesOf(*s));
    };
    for (const RecordEvent &r : records)
        parser.feed(r, sink);
    parser.finish(sink);
    return out;
}

/// A live session on `factory` at `rate`, recorded into `path` with `header` (the decode
/// context goes in as it changes, as the GUI wires it: from the signal, so polling starts once
/// it has been recorded), polled until `samples` samples came. The live samples.
QVector<Values> recordLive(const QString &path, const RecordingHeader &header,
                           bus::TransportFactory factory, int rate,
                           const QMap<int, protocol::Series> &drives, int samples)
{
    auto recorder = std::make_shared<SessionRecorder>();
    auto clock = bus::makeSteadyBusClock();
    QVector<Values> live;
    if (recorder->start(path, header))
        return live;
    {
        bus::BusSession session;
        QObject::connect(&session, &bus::BusSession::telemetryReceived,
                         [&](const bus::TelemetryBatch &b) {
                             for (const TelemetrySample &s : b)
                                 live.append(valuesOf(s));
                         });
        int recordedDrives = 0;
        QObject::connect(&session, &bus::BusSession::knownMotorsChanged,
                         [&](const bus::KnownMotors &m) {
                             recorder->append(contextRecord(clock->nowNs(), m));
                             recordedDrives = int(m.size());
                         });
        session.open(recordingFactory(std::move(factory), recorder, clock), rate);
        const bool polled =
            QTest::qWaitFor([&] { return session.connection().isOpen(); }, 60000) &&
            [&] {
                for (auto it = drives.cbegin(); it != drives.cend(); ++it)
                    session.setSeries(it.key(), it.value());
                return true;
            }() &&
            QTest::qWaitFor([&] { return recordedDrives == drives.size(); }, 60000) && [&] {
                session.startPolling(bus::PollPlan::standard(drives.keys().toVector()));
                return QTest::qWaitFor([&] { return live.size() >= samples; }, 60000);
            }();
        if (!polled)
            live.clear();
        session.close();
    }
    recorder->stop();
    return live;
}

/// Whether every live sample is in `recorded`, in order (a reply the session discarded as
/// late is on the wire, and in the recording, but was no sample); `why` names the first not.
bool inOrder(const QVector<Values> &live, const QVector<Values> &recorded, QString *why)
{
    int j = 0;
    for (int i = 0; i < live.size(); ++i) {
        while (j < recorded.size() && !(recorded[j] == live[i]))
            ++j;
        if (j >= recorded.size()) {
            *why = QStringLiteral("live sample %1 of drive %2 is not in the recording")
                       .arg(i)
                       .arg(live[i].id);
            return false;
        }
        ++j;
    }
    return true;
}

/// Plays a recording whole (load all) and decodes its replies as a tap would: one stream,
/// request and reply told apart by LEN, the context from the recording.
QVector<Values> replay(const QString &path)
{
    ReplayTransport::Options o;
    o.fastForward = true;
    ReplayTransport replay(path, o);
    ContextSnapshot context;
    protocol::StreamParser parser;
    QVector<Values> out;
    bool done = false;
    QObject::connect(&replay, &ReplayTransport::recordPlayed, [&](const RecordEvent &r) {
        if (r.kind == RecordEvent::Kind::Context)
            context = r.context;
    });
    QObject::connect(&replay, &transport::Transport::bytesReceived, [&](const QByteArray &b) {
        parser.feed(b, [&](const protocol::ParseEvent &e) {
            if (!e.isFrame || e.direction != protocol::FrameDirection::Reply)
                return;
            protocol::DecodeContext c;
            for (const DriveContext &d : context)
                if (d.id == e.frame.id) {
                    c.series = d.series.value_or(protocol::Series::MF);
                    c.generation = d.generation;
                }
            const auto reply = protocol::decodeReply(e.frame, c);
            if (const auto s =
                    reply.reply ? TelemetrySample::fromReply(*reply.reply, 0) : std::nullopt)
                out.append(valuesOf(*s));
        });
    });
    QObject::connect(&replay, &ReplayTransport::finished, [&] { done = true; });
    context = {};
    if (!replay.open())
        return out;
    context = replay.header().context;
    QDeadlineTimer deadline(60000);
    while (!done && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    return out;
}

} // namespace

class tst_RecordSession : public QObject {
    Q_OBJECT
private slots:
    void aReplayGivesTheSamplesTheLiveSessionHad()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("live.lkrec"));
        const QVector<Values> live = recordLive(
            path, lk::testsupport::testHeader(), simFactory(), 115200,
            {{3, protocol::Series::MF}, {17, protocol::Series::MS}, {32, protocol::Series::MG}},
            300);
        const QVector<Values> replayed = replay(path);
        qInfo("live %d samples, replayed %d", int(live.size()), int(replayed.size()));
        QVERIFY(live.size() >= 300);
        QString why;
        QVERIFY2(inOrder(live, replayed, &why), qPrintable(why));
        QVERIFY(replayed.size() - live.size() <= live.size() / 100);
        // The MS drive's replies carried power, on replay too.
        const int power = int(record::TelemetryColumns::indexOf(QStringLiteral("power")).value());
        QVERIFY(std::any_of(replayed.cbegin(), replayed.cend(), [&](const Values &v) {
            return v.id == 17 && !std::isnan(v.columns[power]);
        }));
    }

    /// On CAN the recorder wraps a CAN transport: the engine still sees a CAN link through
    /// it (else it would parse RS485 and give no sample), and the recording (LinkKind::Can)
    /// parses as CAN records, each reply with the generation its ID names.
    void aCanSessionRecordsAndDecodesAsCan()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("can.lkrec"));
        RecordingHeader header = lk::testsupport::testHeader();
        header.linkKind = LinkKind::Can;
        header.baud = 1000000;
        header.context.clear();
        const QVector<Values> live =
            recordLive(path, header, canSimFactory(), 1000000,
                       {{1, protocol::Series::MG}, {2, protocol::Series::MF}}, 100);
        const QVector<Values> decoded = decodedReplies(path);
        qInfo("live %d samples, decoded %d", int(live.size()), int(decoded.size()));
        QVERIFY(live.size() >= 100);
        QString why;
        QVERIFY2(inOrder(live, decoded, &why), qPrintable(why));
        QVERIFY(decoded.size() - live.size() <= live.size() / 100);
    }
};

QTEST_GUILESS_MAIN(tst_RecordSession)
#include "tst_recordsession.moc"
