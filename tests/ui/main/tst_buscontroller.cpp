// BusController on the built-in simulated bus: what the operator is told when the link goes;
// and on CAN through Qt's virtualcan, on a port of this process's own so that parallel ctest
// runs do not share a bus: the CAN bus conditions are states of the open link, not failures.

#include <main/BusController.h>
#include <panels/BusModel.h>

#include <transport/CanTransport.h>
#include <transport/SimBusHandle.h>

#include <QtNetwork/QTcpServer>

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using lk::ui::BusController;
using lk::ui::BusModel;
using lk::ui::ConnectionChoice;
using lk::ui::MessageBanner;
using State = lk::transport::Transport::State;

namespace {
constexpr int kWaitMs = 20000; // a loaded machine: generous, never a timing assertion

/// A free TCP port on the loopback interface for this process's virtualcan server.
quint16 freePort()
{
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0))
        return 0;
    return probe.serverPort();
}
} // namespace

class tst_BusController : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void unplugIsReportedOnce();
    void canOpensOverVirtualcan();
    void canConditionIsAStateNotAFailure_data();
    void canConditionIsAStateNotAFailure();
    void canOpenFailureNamesTheInterface();
    void canConditionFollowsTheLinkStatus();

private:
    /// Connect `controller` to this process's virtualcan bus and wait for the link.
    bool openCan(BusController &controller, const QString &channel = QStringLiteral("can0"));
    QString m_server; ///< tcp://127.0.0.1:<port> of this process's virtualcan server
};

void tst_BusController::initTestCase()
{
    qRegisterMetaType<MessageBanner::Level>();
    if (!lk::transport::CanTransport::plugins().contains(QStringLiteral("virtualcan")))
        QFAIL("Qt's virtualcan plugin is missing: install libqt6serialbus6");
    const quint16 port = freePort();
    QVERIFY(port != 0);
    m_server = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
}

bool tst_BusController::openCan(BusController &controller, const QString &channel)
{
    ConnectionChoice choice;
    choice.kind = ConnectionChoice::Kind::Can;
    choice.canPlugin = QStringLiteral("virtualcan");
    choice.canInterface = m_server + QLatin1Char('/') + channel;
    choice.bitRate = 500000;
    choice.autoReconnect = false;
    controller.setScanOnConnect(false);
    controller.connectTo(choice);
    return QTest::qWaitFor([&] { return controller.model()->connection().isOpen(); }, kWaitMs);
}

void tst_BusController::unplugIsReportedOnce()
{
    // An unplug is a state, not an error: one banner message that says what happened and
    // what happens next, not a second one for the same event.
    BusModel model;
    BusController controller(&model);
    controller.setScanOnConnect(false);
    ConnectionChoice choice;
    choice.kind = ConnectionChoice::Kind::Simulator;
    choice.autoReconnect = false;
    controller.connectTo(choice);
    QTRY_VERIFY_WITH_TIMEOUT(model.connection().isOpen(), kWaitMs);
    QSignalSpy messages(&controller, &BusController::message);
    QVERIFY(controller.simulator()->requestDisconnect());
    QTRY_COMPARE_WITH_TIMEOUT(model.connection().state, State::Disconnected, kWaitMs);
    QTest::qWait(300); // anything else the bus thread had to say has arrived
    QCOMPARE(messages.size(), 1);
    QCOMPARE(messages.first().at(0).value<MessageBanner::Level>(), MessageBanner::Level::Warning);
    const QString text = messages.first().at(1).toString();
    QVERIFY2(text.startsWith(QStringLiteral("Lost the link")) &&
                 text.contains(QStringLiteral("simulated bus was disconnected")),
             qPrintable(text));
    QVERIFY2(model.connection().reason.contains(QStringLiteral("simulated bus was disconnected")),
             qPrintable(model.connection().reason));
}

void tst_BusController::canOpensOverVirtualcan()
{
    BusModel model;
    BusController controller(&model);
    QVERIFY(openCan(controller));
    QCOMPARE(model.link(), lk::protocol::Link::Can);
    QCOMPARE(model.canInterface(), QStringLiteral("can0")); // candump's name for the channel
    QVERIFY2(model.connection().description.startsWith(QStringLiteral("virtualcan:")),
             qPrintable(model.connection().description));
    QCOMPARE(model.connection().baud, 500000); // the bit rate chosen
    QCOMPARE(controller.portKey(), QStringLiteral("can:virtualcan:%1/can0").arg(m_server));
    controller.disconnectBus();
    QCOMPARE(model.connection().state, State::Closed);
}

void tst_BusController::canConditionIsAStateNotAFailure_data()
{
    using K = lk::transport::TransportError::Kind;
    using C = lk::transport::CanBusCondition;
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("condition"); ///< the state the model takes; Good: none
    QTest::addColumn<bool>("endsWithAReply");
    QTest::newRow("bus-off") << int(K::CanBusOff) << int(C::BusOff) << true;
    QTest::newRow("error-passive") << int(K::CanErrorPassive) << int(C::ErrorPassive) << false;
    QTest::newRow("no-ack") << int(K::CanNoAcknowledge) << int(C::NoAcknowledge) << true;
    QTest::newRow("one refused frame") << int(K::IoError) << int(C::Good) << false;
    QTest::newRow("bit rate not set") << int(K::BadSettings) << int(C::Good) << false;
}

void tst_BusController::canConditionIsAStateNotAFailure()
{
    QFETCH(int, kind);
    QFETCH(int, condition);
    QFETCH(bool, endsWithAReply);
    BusModel model;
    BusController controller(&model);
    QVERIFY(openCan(controller, QStringLiteral("can1")));
    QSignalSpy messages(&controller, &BusController::message);
    lk::transport::TransportError e;
    e.kind = lk::transport::TransportError::Kind(kind);
    e.message = QStringLiteral("The transport's sentence, with its fix.");
    emit controller.session()->errorOccurred(e); // as the bus thread relays it
    QCOMPARE(messages.size(), 1);
    QCOMPARE(messages.first().at(0).value<MessageBanner::Level>(), MessageBanner::Level::Warning);
    QCOMPARE(messages.first().at(1).toString(), e.message); // said as the transport words it
    QCOMPARE(int(model.canCondition()), condition);
    QVERIFY(model.connection().isOpen()); // never "link lost"
    if (condition != int(lk::transport::CanBusCondition::Good))
        QCOMPARE(model.canConditionMessage(), e.message);
    // A drive's reply crossed the bus: bus-off and no-ACK are over; error-passive is not
    // (frames get through while the counters stay high).
    lk::bus::TelemetrySample sample;
    sample.id = 1;
    emit controller.session()->telemetryReceived({sample});
    QCOMPARE(model.canCondition() == lk::transport::CanBusCondition::Good,
             endsWithAReply || condition == int(lk::transport::CanBusCondition::Good));
    controller.disconnectBus();
    QCOMPARE(model.canCondition(), lk::transport::CanBusCondition::Good);
}

void tst_BusController::canOpenFailureNamesTheInterface()
{
    // An interface that cannot be opened is a failure, named with the plugin and interface.
    BusModel model;
    BusController controller(&model);
    QSignalSpy messages(&controller, &BusController::message);
    ConnectionChoice choice;
    choice.kind = ConnectionChoice::Kind::Can;
    choice.canPlugin = QStringLiteral("nosuchplugin");
    choice.canInterface = QStringLiteral("can7");
    choice.autoReconnect = false;
    controller.setScanOnConnect(false);
    controller.connectTo(choice);
    QTRY_VERIFY_WITH_TIMEOUT(!messages.isEmpty(), kWaitMs);
    QCOMPARE(messages.first().at(0).value<MessageBanner::Level>(), MessageBanner::Level::Error);
    const QString text = messages.first().at(1).toString();
    QVERIFY2(text.startsWith(QStringLiteral("Cannot use nosuchplugin:can7: ")), qPrintable(text));
    QVERIFY(!model.connection().isOpen());
}

QTEST_MAIN(tst_BusController)
// The engine's status carries the CAN condition and reports its end: error-passive, which no
// reply clears, ends when the link says Good again.
void tst_BusController::canConditionFollowsTheLinkStatus()
{
    using C = lk::transport::CanBusCondition;
    BusModel model;
    lk::bus::ConnectionStatus status;
    status.state = lk::transport::Transport::State::Open;
    status.link = lk::protocol::Link::Can;
    status.canCondition = C::ErrorPassive;
    status.conditionText = QStringLiteral("error passive: check termination");
    model.setConnection(status, false);
    QCOMPARE(model.canCondition(), C::ErrorPassive);
    QCOMPARE(model.canConditionMessage(), status.conditionText);
    status.canCondition = C::Good;
    status.conditionText.clear();
    model.setConnection(status, false);
    QCOMPARE(model.canCondition(), C::Good);
    QVERIFY(model.canConditionMessage().isEmpty());
}

#include "tst_buscontroller.moc"
