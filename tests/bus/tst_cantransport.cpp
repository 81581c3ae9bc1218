// CanTransport: the bus states of error frames (bus-off, error-passive, no ACK) as states of
// an open link with their fix, one report for a run of refused writes, the device going away;
// then the real thing against Qt's virtualcan plugin. Qt starts the virtualcan TCP server
// once per process, on the port of the first device that connects, and serves it to every
// process on the machine: this test picks a free port of its own so that parallel ctest runs
// never share a bus.

#include "FakeCanDevice.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <transport/CanTransport.h>

#include <QtCore/QCoreApplication>
#include <QtNetwork/QTcpServer>
#include <QtSerialBus/QCanBus>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

namespace proto = lk::protocol;
using lk::transport::CanBusCondition;
using lk::transport::CanSettings;
using lk::transport::CanTransport;
using lk::transport::Transport;
using lk::transport::TransportError;
using Kind = lk::transport::TransportError::Kind;
using lk::bustest::errorFrame;
using lk::bustest::FakeCanDevice;

namespace {

QCanBusFrame dataFrame(quint32 id, const char *hex)
{
    return QCanBusFrame(id, QByteArray::fromHex(hex));
}

QByteArray recordBytes(quint32 id, const char *hex)
{
    return proto::CanRecord::of(proto::can::CanData{id, QByteArray::fromHex(hex)}).encode();
}

/// A free TCP port on the loopback interface for this process's virtualcan server.
quint16 freePort()
{
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0))
        return 0;
    return probe.serverPort();
}

} // namespace

class tst_CanTransport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void writesRecordsAsFrames();
    void framesWrittenWhileConnectingWaitForTheDevice();
    void busStates_data();
    void busStates();
    void oneReportForARunOfRefusedWrites();
    void bitRateRefusedGivesTheIpLinkCommand();
    void deviceGoingAwayDisconnects();
    void openFailures_data();
    void openFailures();
    void factoryTakesTheSessionsBitRate();
    void overVirtualCan();

private:
    /// A transport over a FakeCanDevice; the device stays owned by the transport.
    std::unique_ptr<CanTransport> fakeTransport(FakeCanDevice **device)
    {
        CanSettings s;
        s.plugin = QStringLiteral("fake");
        return std::make_unique<CanTransport>(s, [device](const CanSettings &, QString *) {
            auto d = std::make_unique<FakeCanDevice>();
            *device = d.get();
            return std::unique_ptr<QCanBusDevice>(std::move(d));
        });
    }
    QString m_url; ///< tcp://127.0.0.1:<port>/can0 of this process
};

void tst_CanTransport::initTestCase()
{
    qRegisterMetaType<TransportError>();
    qRegisterMetaType<CanBusCondition>();
    QVERIFY2(QCanBus::instance()->plugins().contains(QStringLiteral("virtualcan")),
             "Qt's virtualcan plugin is missing: install libqt6serialbus6");
    const quint16 port = freePort();
    QVERIFY(port != 0);
    m_url = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
}

void tst_CanTransport::writesRecordsAsFrames()
{
    FakeCanDevice *dev = nullptr;
    auto t = fakeTransport(&dev);
    QVERIFY(t->open());
    QCOMPARE(t->state(), Transport::State::Open);
    t->write(recordBytes(0x141, "9C00000000000000") + recordBytes(0x142, "A100000064000000"));
    QCOMPARE(dev->written.size(), 2);
    QCOMPARE(dev->written[0].frameId(), 0x141u);
    QCOMPARE(dev->written[0].payload(), QByteArray::fromHex("9C00000000000000"));
    QCOMPARE(dev->written[1].frameId(), 0x142u);
    QVERIFY(!dev->written[1].hasExtendedFrameFormat());
    // Something that is not a record is never put on the bus.
    t->write(QByteArray::fromHex("3E9C0100DB"));
    QCOMPARE(dev->written.size(), 2);
}

void tst_CanTransport::framesWrittenWhileConnectingWaitForTheDevice()
{
    FakeCanDevice *dev = nullptr;
    CanSettings s;
    s.plugin = QStringLiteral("fake");
    CanTransport t(s, [&dev](const CanSettings &, QString *) {
        auto d = std::make_unique<FakeCanDevice>();
        d->connectAtOnce = false; // like virtualcan: connected later, from the event loop
        dev = d.get();
        return std::unique_ptr<QCanBusDevice>(std::move(d));
    });
    QVERIFY(t.open());
    t.write(recordBytes(0x141, "8000000000000000"));
    QCOMPARE(dev->written.size(), 0);
    dev->finishConnecting();
    QCOMPARE(dev->written.size(), 1);
    QCOMPARE(dev->written[0].payload(), QByteArray::fromHex("8000000000000000"));
}

void tst_CanTransport::busStates_data()
{
    QTest::addColumn<int>("errors");
    QTest::addColumn<int>("detail");
    QTest::addColumn<int>("condition");
    QTest::addColumn<int>("kind"); ///< -1: no report
    QTest::addColumn<QString>("words");
    QTest::newRow("bus-off") << int(QCanBusFrame::BusOffError) << 0 << int(CanBusCondition::BusOff)
                             << int(Kind::CanBusOff) << QStringLiteral("restart-ms 100");
    QTest::newRow("no ACK") << int(QCanBusFrame::MissingAcknowledgmentError) << 0
                            << int(CanBusCondition::NoAcknowledge) << int(Kind::CanNoAcknowledge)
                            << QStringLiteral("bit rate");
    QTest::newRow("error-passive (tx)")
        << int(QCanBusFrame::ControllerError) << 0x20 << int(CanBusCondition::ErrorPassive)
        << int(Kind::CanErrorPassive) << QStringLiteral("120 ohm");
    QTest::newRow("error-passive (rx)")
        << int(QCanBusFrame::ControllerError) << 0x10 << int(CanBusCondition::ErrorPassive)
        << int(Kind::CanErrorPassive) << QStringLiteral("1000000 bit/s");
    QTest::newRow("warning: a state, no report")
        << int(QCanBusFrame::ControllerError) << 0x08 << int(CanBusCondition::Warning) << -1
        << QString();
    QTest::newRow("a lone bus error changes nothing")
        << int(QCanBusFrame::BusError) << 0 << int(CanBusCondition::Good) << -1 << QString();
}

void tst_CanTransport::busStates()
{
    QFETCH(int, errors);
    QFETCH(int, detail);
    QFETCH(int, condition);
    QFETCH(int, kind);
    QFETCH(QString, words);
    FakeCanDevice *dev = nullptr;
    auto t = fakeTransport(&dev);
    QVERIFY(t->open());
    QSignalSpy errorsSpy(t.get(), &Transport::errorOccurred);
    QSignalSpy states(t.get(), &Transport::stateChanged);
    QSignalSpy bytes(t.get(), &Transport::bytesReceived);
    const QCanBusFrame e = errorFrame(QCanBusFrame::FrameErrors(errors), quint8(detail));
    dev->receive({e, e, e}); // a burst of the same error frame
    QCOMPARE(int(t->condition()), condition);
    QCOMPARE(t->state(), Transport::State::Open); // never "link lost"
    QCOMPARE(states.count(), 0);
    QCOMPARE(errorsSpy.count(), kind < 0 ? 0 : 1); // once per change, not per frame
    if (kind >= 0) {
        const auto err = errorsSpy[0][0].value<TransportError>();
        QCOMPARE(int(err.kind), kind);
        QVERIFY2(err.message.contains(words), qPrintable(err.message));
        QVERIFY2(err.message.contains(QStringLiteral("fake:can0")), qPrintable(err.message));
    }
    // The error frames reach the parser as error records (not as drive frames).
    QCOMPARE(bytes.count(), 1);
    const QByteArray all = bytes[0][0].toByteArray();
    QCOMPARE(all.size(), 3 * proto::CanRecord::kSize);
    QVERIFY(proto::CanRecord::decode(all.left(proto::CanRecord::kSize))->isError());
    // A drive answering ends bus-off and no-ACK.
    dev->receive({dataFrame(0x141, "9C326400F4010020")});
    if (condition == int(CanBusCondition::BusOff) ||
        condition == int(CanBusCondition::NoAcknowledge))
        QCOMPARE(int(t->condition()), int(CanBusCondition::Good));
    // The controller's own word ends error-passive.
    dev->receive({errorFrame(QCanBusFrame::ControllerError, 0x40)});
    QCOMPARE(int(t->condition()), int(CanBusCondition::Good));
}

void tst_CanTransport::oneReportForARunOfRefusedWrites()
{
    FakeCanDevice *dev = nullptr;
    auto t = fakeTransport(&dev);
    QVERIFY(t->open());
    QSignalSpy errors(t.get(), &Transport::errorOccurred);
    dev->acceptWrites = false;
    for (int i = 0; i < 5; ++i)
        t->write(recordBytes(0x141, "9C00000000000000"));
    QCOMPARE(t->failedWrites(), quint64(5));
    QCOMPARE(errors.count(), 1);
    QCOMPARE(int(errors[0][0].value<TransportError>().kind), int(Kind::IoError));
    QVERIFY(errors[0][0].value<TransportError>().message.contains(QStringLiteral("stays open")));
    QCOMPARE(t->state(), Transport::State::Open);
    // Once a frame got through, the next refusal is news again.
    dev->receive({dataFrame(0x141, "9C326400F4010020")});
    t->write(recordBytes(0x141, "9C00000000000000"));
    QCOMPARE(errors.count(), 2);
}

void tst_CanTransport::bitRateRefusedGivesTheIpLinkCommand()
{
    FakeCanDevice *dev = nullptr;
    auto t = fakeTransport(&dev);
    QVERIFY(t->open());
    QSignalSpy errors(t.get(), &Transport::errorOccurred);
    dev->fail(QStringLiteral("Operation not permitted"), QCanBusDevice::ConfigurationError);
    QCOMPARE(errors.count(), 1);
    const auto e = errors[0][0].value<TransportError>();
    QCOMPARE(int(e.kind), int(Kind::BadSettings));
    QVERIFY2(e.message.contains(QStringLiteral(
                 "ip link set can0 type can bitrate 1000000 && ip link set can0 up")),
             qPrintable(e.message));
    QCOMPARE(t->state(), Transport::State::Open);
}

void tst_CanTransport::deviceGoingAwayDisconnects()
{
    FakeCanDevice *dev = nullptr;
    auto t = fakeTransport(&dev);
    QVERIFY(t->open());
    QSignalSpy errors(t.get(), &Transport::errorOccurred);
    QSignalSpy states(t.get(), &Transport::stateChanged);
    dev->vanish();
    QCOMPARE(t->state(), Transport::State::Disconnected);
    QCOMPARE(errors.count(), 1); // the reason first, once
    QCOMPARE(int(errors[0][0].value<TransportError>().kind), int(Kind::Unplugged));
    QCOMPARE(states.count(), 1);
    t->close();
    QCOMPARE(t->state(), Transport::State::Closed);
}

void tst_CanTransport::openFailures_data()
{
    QTest::addColumn<QString>("plugin");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("words");
    QTest::newRow("no such plugin") << QStringLiteral("nosuchplugin") << int(Kind::CanPluginMissing)
                                    << QStringLiteral("virtualcan");
    QTest::newRow("no such interface")
        << QStringLiteral("virtualcan") << int(Kind::NoSuchPort)
        << QStringLiteral("ip link set can7 type can bitrate 1000000 && ip link set can7 up");
}

void tst_CanTransport::openFailures()
{
    QFETCH(QString, plugin);
    QFETCH(int, kind);
    QFETCH(QString, words);
    CanSettings s;
    s.plugin = plugin;
    s.interfaceName = QStringLiteral("can7"); // virtualcan has can0 and can1 only
    CanTransport t(s);
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(!t.open());
    QCOMPARE(t.state(), Transport::State::Closed);
    QCOMPARE(errors.count(), 1);
    const auto e = errors[0][0].value<TransportError>();
    QCOMPARE(int(e.kind), kind);
    QVERIFY2(e.message.contains(words), qPrintable(e.message));
}

void tst_CanTransport::factoryTakesTheSessionsBitRate()
{
    CanSettings s;
    s.plugin = QStringLiteral("virtualcan");
    s.interfaceName = m_url;
    const auto make = CanTransport::factory(s);
    const std::unique_ptr<Transport> t = make(500000);
    QCOMPARE(t->baud(), 500000);
    QCOMPARE(t->description(), QStringLiteral("virtualcan:%1 @ 500000 bit/s").arg(m_url));
    QCOMPARE(make(0)->baud(), 1000000);
}

void tst_CanTransport::overVirtualCan()
{
    CanSettings s;
    s.plugin = QStringLiteral("virtualcan");
    s.interfaceName = m_url;
    CanTransport tool(s);
    QSignalSpy received(&tool, &Transport::bytesReceived);
    QVERIFY(tool.open());
    QString error;
    std::unique_ptr<QCanBusDevice> drive(
        QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), m_url, &error));
    QVERIFY2(drive, qPrintable(error));
    QVERIFY(drive->connectDevice());
    QTRY_COMPARE(drive->state(), QCanBusDevice::ConnectedState);
    QCOMPARE(tool.state(), Transport::State::Open);
    // The virtualcan server (in this process: the tool connected first) relays a frame only to
    // the clients it has accepted, and it may accept the drive after the drive calls itself
    // connected: a frame the tool wrote before that would never reach the drive (seen under
    // ASan). A frame from the drive that reaches the tool shows the server knows the drive.
    QVERIFY(drive->writeFrame(dataFrame(0x7FF, "00")));
    QTRY_VERIFY(received.count() > 0);
    received.clear();

    // The tool's request arrives at the drive as 141#9C00000000000000.
    tool.write(recordBytes(0x141, "9C00000000000000"));
    QTRY_VERIFY(drive->framesAvailable() > 0);
    const QCanBusFrame request = drive->readFrame();
    QCOMPARE(request.frameId(), 0x141u);
    QCOMPARE(request.payload(), QByteArray::fromHex("9C00000000000000"));

    // The V2.36 reply on 0x181 comes back as one record the CAN parser reads as a reply.
    QVERIFY(drive->writeFrame(dataFrame(0x181, "9C326400F4010020")));
    QTRY_COMPARE(received.count(), 1);
    proto::CanRecordParser parser;
    std::vector<proto::ParseEvent> events;
    parser.feed(received[0][0].toByteArray(),
                [&](const proto::ParseEvent &e) { events.push_back(e); });
    QCOMPARE(int(events.size()), 1);
    QVERIFY(events[0].isFrame);
    QCOMPARE(int(events[0].direction), int(proto::FrameDirection::Reply));
    QCOMPARE(events[0].frame.id, quint8(1));
    QCOMPARE(events[0].frame.command, quint8(0x9C));
    QCOMPARE(events[0].frame.data, QByteArray::fromHex("326400F4010020"));
    QCOMPARE(tool.condition(), CanBusCondition::Good);
    tool.close();
    QCOMPARE(tool.state(), Transport::State::Closed);
}

QTEST_GUILESS_MAIN(tst_CanTransport)
#include "tst_cantransport.moc"
