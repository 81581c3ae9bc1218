// BusController on the built-in simulated bus: what the operator is told when the link goes.

#include <main/BusController.h>
#include <panels/BusModel.h>

#include <transport/SimBusHandle.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using lk::ui::BusController;
using lk::ui::BusModel;
using lk::ui::ConnectionChoice;
using lk::ui::MessageBanner;
using State = lk::transport::Transport::State;

namespace {
constexpr int kWaitMs = 20000; // a loaded machine: generous, never a timing assertion
} // namespace

class tst_BusController : public QObject {
    Q_OBJECT
private slots:
    void unplugIsReportedOnce();
};

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

QTEST_MAIN(tst_BusController)
#include "tst_buscontroller.moc"
