// The whole window on the built-in simulated CAN bus: chosen in the connection bar (RS485/CAN,
// then the built-in simulator in the list of CAN plugins), the scan finds old and V2.36 drives by
// their replies, and the series chooser gives each drive its identity (series, generation, gear
// ratio), remembered for the connection; until a series is known torque stays refused.

#include "MainWindowFixture.h"

#include "../../bus/FakeCanDevice.h"

#include <drive/ControlView.h>
#include <drive/MotionGate.h>
#include <main/DriveViews.h>
#include <panels/BusPanel.h>
#include <panels/ConnectionBar.h>
#include <panels/Format.h>
#include <panels/SeriesChooser.h>
#include <panels/StatusSummary.h>

#include <protocol/RequestBuilder.h>
#include <safety/MotionGuard.h>
#include <transport/CanTransport.h>

#include <QtCore/QMetaObject>

#include <atomic>

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QPushButton>

using lk::protocol::Generation;
using lk::protocol::Link;
using lk::protocol::Series;
using lk::ui::ConnectionChoice;
using namespace lk::uitest;

namespace {

ConnectionChoice simulatedCanChoice()
{
    ConnectionChoice c = simulatorChoice();
    c.simulatedCan = true;
    return c;
}

/// Pick item `index` of a combo as a click would (activated follows).
void activate(QComboBox *combo, int index)
{
    combo->setCurrentIndex(index);
    emit combo->activated(index);
}

} // namespace

class tst_MainWindowCan : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init() { QVERIFY(openWindow()); }
    void cleanup() { closeWindow(); }
    void connectionBarOpensTheSimulatedCanBus();
    void unknownSeriesRefusesTorque();
    void chooserGivesTheIdentityAndRemembersIt();
    void generationChosenWhereTheLinkCannotTell();
    void busStatesAreStatesOfTheLinkNotALoss();

private:
    /// On the simulated CAN bus, its four drives found and polled.
    bool findAllOnCan()
    {
        m_window->connectTo(simulatedCanChoice());
        return QTest::qWaitFor(
            [this] {
                return model()->canSend() && model()->ids() == kSimIds && model()->isPolling();
            },
            kWaitMs);
    }
    lk::ui::SeriesChooser *chooser() const { return m_window->busPanel()->seriesChooser(); }
    QComboBox *chooserCombo(const char *name) const
    {
        return chooser()->findChild<QComboBox *>(QLatin1String(name));
    }
};

void tst_MainWindowCan::connectionBarOpensTheSimulatedCanBus()
{
    auto *bar = m_window->connectionBar();
    activate(bar->findChild<QComboBox *>(QStringLiteral("linkCombo")), 1);
    auto *plugins = bar->findChild<QComboBox *>(QStringLiteral("canPluginCombo"));
    QCOMPARE(plugins->itemText(0), QStringLiteral("Simulator (built-in)"));
    activate(plugins, 0);
    auto *rates = bar->findChild<QComboBox *>(QStringLiteral("bitRateCombo"));
    activate(rates, rates->findData(500000));
    QVERIFY(!bar->findChild<QComboBox *>(QStringLiteral("canInterfaceCombo"))->isEnabled());
    const ConnectionChoice c = bar->choice();
    QVERIFY(c.isSimulator() && c.simulatedCan && !c.isCan());
    QCOMPARE(c.link(), Link::Can);
    bar->findChild<QPushButton *>(QStringLiteral("connectButton"))->click();
    QTRY_VERIFY_WITH_TIMEOUT(model()->ids() == kSimIds && model()->isPolling(), kWaitMs);
    QCOMPARE(model()->link(), Link::Can);
    QCOMPARE(model()->connection().baud, 500000);
    QVERIFY2(model()->connection().description.contains(QStringLiteral("CAN")),
             qPrintable(model()->connection().description));
    QCOMPARE(sim()->link(), Link::Can);
    // Both generations, told by the replies (drive 3 is V2.36, the others old CAN), and no
    // series: CAN has no model read.
    const lk::bus::KnownMotors known = m_window->controller()->session()->knownMotors();
    for (int id : kSimIds) {
        const lk::ui::DriveRecord *d = model()->drive(id);
        QVERIFY(d);
        QCOMPARE(d->generation(), id == 3 ? Generation::V2_35 : Generation::V2_3);
        QVERIFY(!d->series);
        QVERIFY(known.value(id).generationSeen);
    }
    // The poll reaches every drive, each read in its own generation's layout: a V2.36
    // drive's 0.01 V read as the old 0.1 V would be ten times too high; only V2.36 reports
    // its bus current.
    using F = lk::bus::TelemetryField;
    QTRY_VERIFY_WITH_TIMEOUT(
        model()->drive(1)->has(F::Voltage) && model()->drive(3)->has(F::Voltage), kWaitMs);
    for (int id : {1, 3}) {
        const double volts = model()->drive(id)->latest.voltageV;
        QVERIFY2(volts > 5 && volts < 60, qPrintable(QString::number(volts)));
    }
    QVERIFY(model()->drive(3)->has(F::BusCurrent));
    QVERIFY(!model()->drive(1)->has(F::BusCurrent));
    // Remembered as the simulated CAN bus.
    const ConnectionChoice saved = m_settings->connection();
    QVERIFY(saved.isSimulator() && saved.simulatedCan);
    QCOMPARE(saved.bitRate, 500000);
    QCOMPARE(m_window->controller()->portKey(), QStringLiteral("simulator-can"));
}

void tst_MainWindowCan::unknownSeriesRefusesTorque()
{
    QVERIFY(findAllOnCan());
    model()->setCurrentId(1);
    QTRY_VERIFY_WITH_TIMEOUT(chooser()->isVisible(), kWaitMs);
    lk::protocol::DecodeContext context;
    context.link = Link::Can;
    const lk::ui::MotionOutcome out =
        m_window->driveViews()->control()->sendMotion(lk::protocol::build::torque(1, 0.5, context));
    QVERIFY(!out.sent);
    QCOMPARE(out.limit, lk::safety::LimitKind::UnknownSeries);
    QCOMPARE(sim()->requestCount(1, lk::protocol::Command::Torque), 0);
}

void tst_MainWindowCan::chooserGivesTheIdentityAndRemembersIt()
{
    QVERIFY(findAllOnCan());
    model()->setCurrentId(1);
    QTRY_VERIFY_WITH_TIMEOUT(chooser()->isVisible(), kWaitMs);
    QVERIFY(chooserCombo("generationCombo")->isVisible()); // CAN: the generation is offered
    auto *ratio = chooser()->findChild<QDoubleSpinBox *>(QStringLiteral("gearRatioSpin"));
    ratio->setValue(36);
    emit ratio->editingFinished();
    QComboBox *series = chooserCombo("seriesCombo");
    activate(series, series->findData(static_cast<int>(Series::MG)));
    lk::bus::BusSession *session = m_window->controller()->session();
    auto identity = session->driveIdentity(1);
    QVERIFY(identity);
    QCOMPARE(identity->series, Series::MG);
    QCOMPARE(identity->generation, Generation::V2_3); // as the replies told
    QCOMPARE(identity->gearRatio, std::optional<double>(36));
    QTRY_COMPARE_WITH_TIMEOUT(model()->drive(1)->series, std::optional<Series>(Series::MG),
                              kWaitMs);
    // Remembered for this connection: a new window on the same settings applies it again.
    m_window.reset();
    m_window = std::make_unique<lk::ui::MainWindow>(m_settings.get());
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(findAllOnCan());
    QTRY_VERIFY_WITH_TIMEOUT(m_window->controller()->session()->driveIdentity(1).has_value(),
                             kWaitMs);
    identity = m_window->controller()->session()->driveIdentity(1);
    QCOMPARE(identity->series, Series::MG);
    QCOMPARE(identity->generation, Generation::V2_3);
    QTRY_COMPARE_WITH_TIMEOUT(model()->drive(1)->series, std::optional<Series>(Series::MG),
                              kWaitMs);
    // Not for the other drives.
    QVERIFY(!m_window->controller()->session()->driveIdentity(2));
}

void tst_MainWindowCan::generationChosenWhereTheLinkCannotTell()
{
    QVERIFY(findAllOnCan());
    model()->setCurrentId(4);
    QTRY_VERIFY_WITH_TIMEOUT(chooser()->isVisible(), kWaitMs);
    // A V2.36 drive may answer on 0x140+ID, as the old generation does: the user says it.
    QComboBox *generation = chooserCombo("generationCombo");
    activate(generation, generation->findData(static_cast<int>(Generation::V2_35)));
    lk::bus::BusSession *session = m_window->controller()->session();
    QVERIFY(!session->driveIdentity(4)); // no series yet: nothing made up
    QCOMPARE(model()->drive(4)->generation(), Generation::V2_35);
    QComboBox *series = chooserCombo("seriesCombo");
    activate(series, series->findData(static_cast<int>(Series::MH)));
    const auto identity = session->driveIdentity(4);
    QVERIFY(identity);
    QCOMPARE(identity->series, Series::MH);
    QCOMPARE(identity->generation, Generation::V2_35);
    QCOMPARE(m_settings->chosenGeneration(QStringLiteral("simulator-can"), 4),
             std::optional<Generation>(Generation::V2_35));
}

// A CAN controller's bus-off and no-ACK, and a frame the device refuses, come from the
// transport through the session to the window: the connection bar names the condition, the
// banner gives the transport's fix, and the link stays open: never "link lost".
void tst_MainWindowCan::busStatesAreStatesOfTheLinkNotALoss()
{
    using lk::bustest::FakeCanDevice;
    using lk::transport::CanBusCondition;
    std::atomic<FakeCanDevice *> device{nullptr};
    m_window->controller()->addFactoryWrapper(
        [&device](lk::bus::TransportFactory, const ConnectionChoice &choice) {
            return lk::bus::TransportFactory([&device, choice](int bitRate) {
                lk::transport::CanSettings s = lk::ui::BusController::canSettings(choice);
                s.bitRate = bitRate;
                s.setBitRate = false;
                return std::unique_ptr<lk::transport::Transport>(
                    std::make_unique<lk::transport::CanTransport>(
                        s, [&device](const lk::transport::CanSettings &, QString *) {
                            auto d = std::make_unique<FakeCanDevice>();
                            device = d.get();
                            return std::unique_ptr<QCanBusDevice>(std::move(d));
                        }));
            });
        });
    ConnectionChoice c = simulatorChoice();
    c.kind = ConnectionChoice::Kind::Can;
    c.canPlugin = QStringLiteral("socketcan");
    c.canInterface = QStringLiteral("can0");
    m_window->connectTo(c);
    QTRY_VERIFY_WITH_TIMEOUT(model()->connection().isOpen() && device.load(), kWaitMs);
    FakeCanDevice *dev = device.load();
    // On the bus thread, as the device would.
    const auto onBus = [dev](std::function<void()> f) {
        QMetaObject::invokeMethod(dev, std::move(f), Qt::BlockingQueuedConnection);
    };
    auto *bar = m_window->connectionBar();
    const auto noLoss = [this, bar] {
        return model()->connection().isOpen() &&
               !bar->stateText().contains(QStringLiteral("Disconnected")) &&
               !m_window->banner()->text().contains(QStringLiteral("Lost the link"));
    };

    onBus([dev] { dev->receive({lk::bustest::errorFrame(QCanBusFrame::BusOffError)}); });
    QTRY_COMPARE_WITH_TIMEOUT(model()->canCondition(), CanBusCondition::BusOff, kWaitMs);
    QVERIFY2(bar->stateText().contains(lk::ui::Format::canCondition(CanBusCondition::BusOff)),
             qPrintable(bar->stateText()));
    // The status bar says it whole: the connection bar's copy may be cut short on a narrow
    // screen.
    QCOMPARE(m_window->statusSummary()->linkText(), bar->stateText());
    QTRY_VERIFY2_WITH_TIMEOUT(m_window->banner()->text().contains(QStringLiteral("restart-ms")),
                              qPrintable(m_window->banner()->text()), kWaitMs);
    QVERIFY(noLoss());

    // One refused write: reported once, the link stays open.
    onBus([dev] { dev->acceptWrites = false; });
    m_window->controller()->session()->send(
        *lk::protocol::build::plain(lk::protocol::Command::ReadState1, 1).request);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->banner()->text().contains(QStringLiteral("stays open")),
                             kWaitMs);
    QTest::qWait(300); // whatever else the bus thread had to say has arrived
    QVERIFY2(noLoss(),
             qPrintable(bar->stateText() + QLatin1Char('\n') + m_window->banner()->text()));
    QCOMPARE(model()->connection().state, lk::transport::Transport::State::Open);

    onBus([dev] {
        dev->acceptWrites = true;
        dev->receive({lk::bustest::errorFrame(QCanBusFrame::MissingAcknowledgmentError)});
    });
    QTRY_COMPARE_WITH_TIMEOUT(model()->canCondition(), CanBusCondition::NoAcknowledge, kWaitMs);
    QVERIFY2(
        bar->stateText().contains(lk::ui::Format::canCondition(CanBusCondition::NoAcknowledge)),
        qPrintable(bar->stateText()));
    QVERIFY(noLoss());
    QVERIFY2(!m_window->statusSummary()->linkText().startsWith(QStringLiteral("Disconnected")),
             qPrintable(m_window->statusSummary()->linkText()));
}

QTEST_MAIN(tst_MainWindowCan)
#include "tst_mainwindowcan.moc"
