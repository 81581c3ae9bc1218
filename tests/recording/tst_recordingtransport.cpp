// RecordingTransport and recordingFactory: the bus engine sees the inner transport unchanged,
// and the sink gets every tx and rx chunk, open, close, error and baud change, on the clock.
#include "../bus/FakeTransport.h"
#include "../support/ManualClock.h"

#include <recording/RecordingTransport.h>
#include <recording/SessionRecorder.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace lk::recording;
using lk::bustest::FakeTransport;
using lk::testsupport::ManualClock;
using lk::transport::Transport;

namespace {

/// Keeps what it is given.
struct ListSink : RecordSink {
    QVector<RecordEvent> events;
    void append(RecordEvent event) override { events.append(std::move(event)); }
};

} // namespace

class tst_RecordingTransport : public QObject {
    Q_OBJECT
private slots:
    /// Listen-only reaches the transport that owns the port: it opens read-only, and a write
    /// that still came is refused before it reaches it or the recording.
    void listenOnlyReachesTheWrappedTransport()
    {
        auto sink = std::make_shared<ListSink>();
        auto *fake = new FakeTransport(115200);
        RecordingTransport t(std::unique_ptr<Transport>(fake), sink,
                             std::make_shared<ManualClock>());
        t.setReadOnly(true);
        QVERIFY(t.open());
        QCOMPARE(fake->log()->readOnly.value(0), true);
        t.write(QByteArray::fromHex("3e9c0100db"));
        QCOMPARE(fake->log()->writtenCopy().size(), 0);
        QCOMPARE(t.refusedWrites(), quint64(5));
        for (const RecordEvent &e : sink->events)
            QVERIFY(e.kind != RecordEvent::Kind::Tx);
    }
    /// A CAN link's bus condition (bus-off, no-ACK) passes through the recorder: the GUI always
    /// records, and without this the engine never heard of a bus-off.
    void forwardsTheCanBusCondition()
    {
        auto *fake = new FakeTransport(1000000);
        RecordingTransport t(std::unique_ptr<Transport>(fake), std::make_shared<ListSink>(),
                             std::make_shared<ManualClock>());
        QSignalSpy spy(&t, &Transport::canConditionChanged);
        emit fake->canConditionChanged(lk::transport::CanBusCondition::BusOff);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).value<lk::transport::CanBusCondition>(),
                 lk::transport::CanBusCondition::BusOff);
    }
    void forwardsAndRecordsBothDirections()
    {
        auto sink = std::make_shared<ListSink>();
        auto clock = std::make_shared<ManualClock>();
        auto *fake = new FakeTransport(115200);
        fake->setResponder([](const lk::protocol::Frame &, int) {
            return QByteArray::fromHex("3e9c0107e21ff40168010030ad");
        });
        RecordingTransport t(std::unique_ptr<Transport>(fake), sink, clock);
        QSignalSpy received(&t, &Transport::bytesReceived);
        QSignalSpy states(&t, &Transport::stateChanged);
        clock->setNs(1000);
        QVERIFY(t.open());
        QCOMPARE(t.state(), Transport::State::Open);
        QCOMPARE(t.baud(), 115200);
        QCOMPARE(t.description(), fake->description());
        clock->setNs(2000);
        const QByteArray request = QByteArray::fromHex("3e9c0100db");
        t.write(request);
        QCOMPARE(fake->log()->writtenCopy().value(0), request);
        clock->setNs(5000);
        QTRY_COMPARE(received.size(), 1);
        QCOMPARE(received.at(0).at(0).toByteArray(),
                 QByteArray::fromHex("3e9c0107e21ff40168010030ad"));
        clock->setNs(9000);
        fake->unplug();
        QTRY_VERIFY(!states.isEmpty());
        t.write(request); // disconnected: not on the wire, not recorded
        QCOMPARE(sink->events.size(), 5);
        QCOMPARE(int(sink->events[0].kind), int(RecordEvent::Kind::Link));
        QCOMPARE(int(sink->events[0].link), int(LinkEventKind::Opened));
        QCOMPARE(sink->events[0].baud, 115200);
        QCOMPARE(sink->events[0].timeNs, qint64(1000));
        QCOMPARE(int(sink->events[1].kind), int(RecordEvent::Kind::Tx));
        QCOMPARE(sink->events[1].bytes, request);
        QCOMPARE(sink->events[1].timeNs, qint64(2000));
        QCOMPARE(int(sink->events[2].kind), int(RecordEvent::Kind::Rx));
        QCOMPARE(sink->events[2].timeNs, qint64(5000));
        QCOMPARE(int(sink->events[3].link), int(LinkEventKind::Error));
        QCOMPARE(int(sink->events[4].link), int(LinkEventKind::Disconnected));
        QCOMPARE(sink->events[4].timeNs, qint64(9000));
    }

    void factoryRecordsABaudChangeIntoOneSink()
    {
        auto sink = std::make_shared<ListSink>();
        auto clock = std::make_shared<ManualClock>();
        const auto factory = recordingFactory(
            [](int baud) { return std::make_unique<FakeTransport>(baud); }, sink, clock);
        auto first = factory(115200);
        QVERIFY(first->open());
        first->close();
        auto second = factory(1000000);
        QVERIFY(second->open());
        QCOMPARE(second->baud(), 1000000);
        QCOMPARE(sink->events.size(), 4);
        QCOMPARE(int(sink->events[1].link), int(LinkEventKind::Closed));
        QCOMPARE(int(sink->events[2].link), int(LinkEventKind::BaudChanged));
        QCOMPARE(sink->events[2].baud, 1000000);
        QCOMPARE(int(sink->events[3].link), int(LinkEventKind::Opened));
    }

    void aFailedRecordingLeavesTheSessionRunning()
    {
        // The recorder could not even start (/dev/full): the transport still moves bytes.
        auto recorder = std::make_shared<SessionRecorder>();
        QVERIFY(recorder->start(QStringLiteral("/dev/full"), RecordingHeader{}));
        auto clock = std::make_shared<ManualClock>();
        auto *fake = new FakeTransport(115200);
        RecordingTransport t(std::unique_ptr<Transport>(fake), recorder, clock);
        QSignalSpy received(&t, &Transport::bytesReceived);
        QVERIFY(t.open());
        t.write(QByteArray::fromHex("3e9c0100db"));
        QCOMPARE(fake->log()->writtenCopy().size(), 1);
        fake->inject("abc");
        QTRY_COMPARE(received.size(), 1);
    }
};

QTEST_GUILESS_MAIN(tst_RecordingTransport)
#include "tst_recordingtransport.moc"
