#include <panels/ConnectionBar.h>
#include <panels/ElidedLabel.h>

#include <QtTest/QtTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>

using lk::ui::ConnectionBar;
using lk::ui::ConnectionChoice;
using lk::ui::PortEntry;

namespace {

PortEntry ftdi()
{
    PortEntry p;
    p.name = QStringLiteral("ttyUSB0");
    p.location = QStringLiteral("/dev/ttyUSB0");
    p.description = QStringLiteral("FT232R USB UART");
    p.vendorId = 0x0403;
    p.productId = 0x6001;
    return p;
}

PortEntry ch340()
{
    PortEntry p;
    p.name = QStringLiteral("ttyUSB1");
    p.location = QStringLiteral("/dev/ttyUSB1");
    p.description = QStringLiteral("USB Serial");
    p.vendorId = 0x1a86;
    p.productId = 0x7523;
    return p;
}

/// A bar on fake serial ports and a fake Qt CAN list: socketcan with can0 and vcan0,
/// virtualcan with can0 and can1.
void fakeCan(ConnectionBar &bar, const QStringList *socketcan = nullptr)
{
    bar.setPortLister([] { return QList<PortEntry>{ftdi()}; });
    bar.setCanListers(
        [] {
            return QStringList{QStringLiteral("socketcan"), QStringLiteral("virtualcan")};
        },
        [socketcan](const QString &plugin) {
            if (plugin == QLatin1String("socketcan"))
                return socketcan ? *socketcan
                                 : QStringList{QStringLiteral("can0"), QStringLiteral("vcan0")};
            if (plugin == QLatin1String("virtualcan"))
                return QStringList{QStringLiteral("can0"), QStringLiteral("can1")};
            return QStringList{};
        });
}

/// A CAN link that is open and may transmit, as the session reports it.
lk::bus::ConnectionStatus openCan()
{
    lk::bus::ConnectionStatus s;
    s.state = lk::transport::Transport::State::Open;
    s.canTransmit = true;
    s.description = QStringLiteral("socketcan:can0 @ 1000000 bit/s");
    return s;
}

QComboBox *combo(ConnectionBar &bar, const char *name)
{
    return bar.findChild<QComboBox *>(QLatin1String(name));
}

} // namespace

class tst_ConnectionBar : public QObject {
    Q_OBJECT
private slots:
    void label_data();
    void label();
    void listsBaudsAndSimulator();
    void adaptersComeAndGo();
    void keepsChoiceAcrossRefresh();
    void connectEmitsChoice();
    void typedPathIsSerial();
    void lockedWhileOpen();
    void listenOnlyIsPartOfTheChoice();
    void listeningSaysSoAndOffersTakeOver_data();
    void listeningSaysSoAndOffersTakeOver();
    void canListsPluginsInterfacesAndBitRates();
    void canChoiceRoundTrip();
    void canInterfacesComeAndGo();
    void canWidgetsLockedWhileOpen();
    void canConditionIsAStateNotALoss_data();
    void canConditionIsAStateNotALoss();
    void stateGivesUpWidthFirst();
};

void tst_ConnectionBar::label_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("text");
    QTest::newRow("ftdi") << 0 << QStringLiteral("ttyUSB0 \u2013 FT232R USB UART (0403:6001)");
    QTest::newRow("ch340") << 1 << QStringLiteral("ttyUSB1 \u2013 USB Serial (1a86:7523)");
    QTest::newRow("bare") << 2 << QStringLiteral("ttyS0");
}

void tst_ConnectionBar::label()
{
    QFETCH(int, which);
    QFETCH(QString, text);
    PortEntry bare;
    bare.name = QStringLiteral("ttyS0");
    const PortEntry entries[] = {ftdi(), ch340(), bare};
    QCOMPARE(entries[which].label(), text);
}

void tst_ConnectionBar::listsBaudsAndSimulator()
{
    ConnectionBar bar;
    bar.setPortLister([] { return QList<PortEntry>{}; });
    auto *baud = bar.findChild<QComboBox *>(QStringLiteral("baudCombo"));
    auto *port = bar.findChild<QComboBox *>(QStringLiteral("portCombo"));
    QCOMPARE(baud->count(), 10); // V2.3's nine and V2.35's 4 Mbaud
    QCOMPARE(baud->currentText(), QStringLiteral("115200"));
    QCOMPARE(port->count(), 1);
    QVERIFY(bar.choice().isSimulator());
}

void tst_ConnectionBar::adaptersComeAndGo()
{
    ConnectionBar bar;
    QList<PortEntry> present;
    bar.setPortLister([&present] { return present; });
    QSignalSpy changed(&bar, &ConnectionBar::portsChanged);
    auto *port = bar.findChild<QComboBox *>(QStringLiteral("portCombo"));

    present = {ftdi()};
    // The bar polls by itself about once a second.
    QTRY_COMPARE_WITH_TIMEOUT(port->count(), 2, 10000);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(port->itemText(1), ftdi().label());

    present = {ftdi(), ch340()};
    QTRY_COMPARE_WITH_TIMEOUT(port->count(), 3, 10000);
    present = {ch340()};
    QTRY_COMPARE_WITH_TIMEOUT(port->count(), 2, 10000);
    QCOMPARE(port->itemText(1), ch340().label());
    const int before = changed.count();
    bar.refreshPorts(); // same set: nothing to tell
    QCOMPARE(changed.count(), before);
}

void tst_ConnectionBar::keepsChoiceAcrossRefresh()
{
    ConnectionBar bar;
    QList<PortEntry> present{ftdi(), ch340()};
    bar.setPortLister([&present] { return present; });
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Serial;
    c.port = QStringLiteral("/dev/ttyUSB1");
    c.baud = 460800;
    c.autoReconnect = false;
    bar.setChoice(c);
    QCOMPARE(bar.choice(), c);
    present = {ch340()}; // the other adapter leaves
    bar.refreshPorts();
    QCOMPARE(bar.choice(), c);
    present = {}; // ours leaves too: the name stays, typed in
    bar.refreshPorts();
    QCOMPARE(bar.choice(), c);
}

void tst_ConnectionBar::connectEmitsChoice()
{
    ConnectionBar bar;
    bar.setPortLister([] { return QList<PortEntry>{ftdi()}; });
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    auto *port = bar.findChild<QComboBox *>(QStringLiteral("portCombo"));
    auto *baud = bar.findChild<QComboBox *>(QStringLiteral("baudCombo"));
    auto *button = bar.findChild<QPushButton *>(QStringLiteral("connectButton"));
    port->setCurrentIndex(1);
    baud->setCurrentIndex(baud->findText(QStringLiteral("1000000")));
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(connectSpy.count(), 1);
    const auto c = connectSpy.at(0).at(0).value<ConnectionChoice>();
    QCOMPARE(int(c.kind), int(ConnectionChoice::Kind::Serial));
    QCOMPARE(c.port, QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(c.baud, 1000000);
}

void tst_ConnectionBar::typedPathIsSerial()
{
    ConnectionBar bar;
    bar.setPortLister([] { return QList<PortEntry>{}; });
    auto *port = bar.findChild<QComboBox *>(QStringLiteral("portCombo"));
    port->lineEdit()->clear();
    QTest::keyClicks(port->lineEdit(), QStringLiteral("/dev/pts/5"));
    const ConnectionChoice c = bar.choice();
    QCOMPARE(int(c.kind), int(ConnectionChoice::Kind::Serial));
    QCOMPARE(c.port, QStringLiteral("/dev/pts/5"));
}

void tst_ConnectionBar::lockedWhileOpen()
{
    ConnectionBar bar;
    bar.setPortLister([] { return QList<PortEntry>{}; });
    QSignalSpy disconnectSpy(&bar, &ConnectionBar::disconnectRequested);
    auto *port = bar.findChild<QComboBox *>(QStringLiteral("portCombo"));
    auto *button = bar.findChild<QPushButton *>(QStringLiteral("connectButton"));
    lk::bus::ConnectionStatus s;
    s.state = lk::transport::Transport::State::Open;
    s.description = QStringLiteral("Simulated bus (4 drives)");
    bar.setConnectionStatus(s);
    QVERIFY(!port->isEnabled());
    QCOMPARE(button->text(), QStringLiteral("Disconnect"));
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(disconnectSpy.count(), 1);
    s.state = lk::transport::Transport::State::Disconnected;
    bar.setConnectionStatus(s);
    QVERIFY(!port->isEnabled()); // still "connected" to that port, waiting for it
    s.state = lk::transport::Transport::State::Closed;
    bar.setConnectionStatus(s);
    QVERIFY(port->isEnabled());
    QCOMPARE(button->text(), QStringLiteral("Connect"));
}

void tst_ConnectionBar::listenOnlyIsPartOfTheChoice()
{
    ConnectionBar bar;
    bar.setPortLister([] { return QList<PortEntry>{ftdi()}; });
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    auto *listen = bar.findChild<QCheckBox *>(QStringLiteral("listenOnly"));
    QVERIFY(listen);
    QVERIFY(!bar.choice().listenOnly);
    listen->setChecked(true);
    QVERIFY(bar.choice().listenOnly);
    QTest::mouseClick(bar.findChild<QPushButton *>(QStringLiteral("connectButton")),
                      Qt::LeftButton);
    QVERIFY(connectSpy.at(0).at(0).value<ConnectionChoice>().listenOnly);
    ConnectionChoice c = bar.choice();
    c.listenOnly = false;
    bar.setChoice(c);
    QVERIFY(!listen->isChecked());
    lk::bus::ConnectionStatus s;
    s.state = lk::transport::Transport::State::Open;
    bar.setConnectionStatus(s);
    QVERIFY(!listen->isEnabled()); // the mode of an open link changes only by taking over
}

void tst_ConnectionBar::listeningSaysSoAndOffersTakeOver_data()
{
    QTest::addColumn<int>("state");
    QTest::addColumn<bool>("canTransmit");
    QTest::addColumn<bool>("takeOver");
    QTest::addColumn<QString>("text");
    using S = lk::transport::Transport::State;
    QTest::newRow("listening") << int(S::Open) << false << true
                               << "Listen-only: this tool transmits nothing (/dev/ttyUSB0 @ "
                                  "115200)";
    QTest::newRow("master") << int(S::Open) << true << false << "Connected: /dev/ttyUSB0 @ 115200";
    QTest::newRow("closed") << int(S::Closed) << false << false << "Not connected";
    QTest::newRow("lost") << int(S::Disconnected) << false << false << "Disconnected";
}

void tst_ConnectionBar::listeningSaysSoAndOffersTakeOver()
{
    QFETCH(int, state);
    QFETCH(bool, canTransmit);
    QFETCH(bool, takeOver);
    QFETCH(QString, text);
    ConnectionBar bar;
    bar.setPortLister([] { return QList<PortEntry>{}; });
    bar.show();
    lk::bus::ConnectionStatus s;
    s.state = lk::transport::Transport::State(state);
    s.description = QStringLiteral("/dev/ttyUSB0 @ 115200");
    s.canTransmit = canTransmit;
    s.mode = canTransmit ? lk::bus::LinkMode::Active : lk::bus::LinkMode::ListenOnly;
    bar.setConnectionStatus(s);
    QCOMPARE(bar.stateText(), text);
    QCOMPARE(bar.takeOverButton()->isVisible(), takeOver);
    QSignalSpy asked(&bar, &ConnectionBar::takeOverRequested);
    if (takeOver) {
        QTest::mouseClick(bar.takeOverButton(), Qt::LeftButton);
        QCOMPARE(asked.count(), 1); // a request only: MainWindow asks before anything happens
    }
}

void tst_ConnectionBar::canListsPluginsInterfacesAndBitRates()
{
    ConnectionBar bar;
    fakeCan(bar);
    bar.show();
    auto *link = combo(bar, "linkCombo");
    QCOMPARE(link->count(), 2);
    QVERIFY(combo(bar, "portCombo")->isVisible());
    QVERIFY(!combo(bar, "canPluginCombo")->isVisible());
    link->setCurrentIndex(1);
    emit link->activated(1); // as a click does
    QVERIFY(!combo(bar, "portCombo")->isVisible());
    QVERIFY(combo(bar, "canPluginCombo")->isVisible());
    auto *plugin = combo(bar, "canPluginCombo");
    auto *iface = combo(bar, "canInterfaceCombo");
    auto *rate = combo(bar, "bitRateCombo");
    QCOMPARE(plugin->count(), 3); // the built-in simulated CAN bus first, then Qt's plugins
    QCOMPARE(plugin->itemText(0), QStringLiteral("Simulator (built-in)"));
    QCOMPARE(plugin->currentText(), QStringLiteral("socketcan"));
    QCOMPARE(iface->count(), 2);
    QCOMPARE(iface->itemText(1), QStringLiteral("vcan0"));
    QCOMPARE(rate->count(), 5);
    QCOMPARE(rate->currentText(), QStringLiteral("1 Mbit/s")); // LK's factory rate
    QCOMPARE(rate->itemText(1), QStringLiteral("500 kbit/s"));
    QCOMPARE(rate->itemText(3), QStringLiteral("125 kbit/s"));

    // Another plugin lists its own interfaces.
    plugin->setCurrentIndex(2);
    emit plugin->activated(2);
    QCOMPARE(iface->itemText(1), QStringLiteral("can1"));

    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    iface->setCurrentIndex(1);
    rate->setCurrentIndex(rate->findData(500000));
    QTest::mouseClick(bar.findChild<QPushButton *>(QStringLiteral("connectButton")),
                      Qt::LeftButton);
    QCOMPARE(connectSpy.count(), 1);
    const auto c = connectSpy.at(0).at(0).value<ConnectionChoice>();
    QVERIFY(c.isCan());
    QCOMPARE(c.canPlugin, QStringLiteral("virtualcan"));
    QCOMPARE(c.canInterface, QStringLiteral("can1"));
    QCOMPARE(c.bitRate, 500000);
}

void tst_ConnectionBar::canChoiceRoundTrip()
{
    ConnectionBar bar;
    fakeCan(bar);
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Can;
    c.port = QStringLiteral("/dev/ttyUSB0"); // the RS485 port stays for when RS485 comes back
    c.canPlugin = QStringLiteral("socketcan");
    c.canInterface = QStringLiteral("vcan0");
    c.bitRate = 250000;
    bar.setChoice(c);
    QCOMPARE(bar.choice(), c);
    // An interface that is not up yet (not listed) is kept as typed.
    c.canInterface = QStringLiteral("slcan0");
    bar.setChoice(c);
    QCOMPARE(bar.choice(), c);
    // Back to RS485: the serial port chosen before is still there.
    c.kind = ConnectionChoice::Kind::Serial;
    bar.setChoice(c);
    QCOMPARE(bar.choice(), c);
    QCOMPARE(combo(bar, "linkCombo")->currentIndex(), 0);
    // The built-in simulator on CAN: kept apart from the RS485 one, no interface to choose.
    c.kind = ConnectionChoice::Kind::Simulator;
    c.simulatedCan = true;
    bar.setChoice(c);
    QCOMPARE(bar.choice(), c);
    QCOMPARE(bar.choice().link(), lk::protocol::Link::Can);
    QCOMPARE(combo(bar, "linkCombo")->currentIndex(), 1);
    QCOMPARE(combo(bar, "canPluginCombo")->currentIndex(), 0);
    QVERIFY(!combo(bar, "canInterfaceCombo")->isEnabled());
    c.simulatedCan = false; // the simulator on RS485: the port combo's first entry
    c.port.clear();
    bar.setChoice(c);
    QCOMPARE(bar.choice(), c);
    QCOMPARE(combo(bar, "linkCombo")->currentIndex(), 0);
    QCOMPARE(combo(bar, "portCombo")->currentIndex(), 0);
}

void tst_ConnectionBar::canInterfacesComeAndGo()
{
    ConnectionBar bar;
    QStringList up{QStringLiteral("can0")};
    fakeCan(bar, &up);
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Can;
    c.canInterface = QStringLiteral("can0");
    bar.setChoice(c);
    auto *iface = combo(bar, "canInterfaceCombo");
    QCOMPARE(iface->count(), 1);
    up << QStringLiteral("can1"); // a second adapter comes up: listed within the refresh
    QTRY_COMPARE_WITH_TIMEOUT(iface->count(), 2, 10000);
    QCOMPARE(bar.choice().canInterface, QStringLiteral("can0"));
    up = QStringList{QStringLiteral("can1")}; // ours goes away: its name stays chosen
    QTRY_COMPARE_WITH_TIMEOUT(iface->count(), 1, 10000);
    QCOMPARE(bar.choice().canInterface, QStringLiteral("can0"));
}

void tst_ConnectionBar::canWidgetsLockedWhileOpen()
{
    ConnectionBar bar;
    fakeCan(bar);
    lk::bus::ConnectionStatus s;
    s.state = lk::transport::Transport::State::Open;
    s.canTransmit = true;
    bar.setConnectionStatus(s);
    for (const char *name : {"linkCombo", "canPluginCombo", "canInterfaceCombo", "bitRateCombo"})
        QVERIFY2(!combo(bar, name)->isEnabled(), name);
    s.state = lk::transport::Transport::State::Closed;
    bar.setConnectionStatus(s);
    for (const char *name : {"linkCombo", "canPluginCombo", "canInterfaceCombo", "bitRateCombo"})
        QVERIFY2(combo(bar, name)->isEnabled(), name);
}

void tst_ConnectionBar::canConditionIsAStateNotALoss_data()
{
    using C = lk::transport::CanBusCondition;
    QTest::addColumn<int>("condition");
    QTest::addColumn<QString>("said");
    QTest::newRow("bus-off") << int(C::BusOff) << "CAN bus-off: the adapter stopped sending";
    QTest::newRow("error-passive") << int(C::ErrorPassive) << "CAN error-passive: many frames fail";
    QTest::newRow("no-ack") << int(C::NoAcknowledge)
                            << "no acknowledgement: no drive powered, or another bit rate";
}

void tst_ConnectionBar::canConditionIsAStateNotALoss()
{
    QFETCH(int, condition);
    QFETCH(QString, said);
    ConnectionBar bar;
    fakeCan(bar);
    lk::bus::ConnectionStatus s = openCan();
    bar.setConnectionStatus(s);
    const QString fix = QStringLiteral("Check the drives' power, the wiring and the bit rate.");
    bar.setCanCondition(lk::transport::CanBusCondition(condition), fix);
    const QString text = bar.stateText();
    QVERIFY2(text.startsWith(QStringLiteral("Connected: socketcan:can0")), qPrintable(text));
    QVERIFY2(text.endsWith(said), qPrintable(text));
    QVERIFY(!text.contains(QStringLiteral("lost"), Qt::CaseInsensitive));
    auto *state = bar.findChild<QLabel *>(QStringLiteral("connectionState"));
    QVERIFY(state->toolTip().contains(fix)); // the transport's sentence with its fix
    QCOMPARE(bar.findChild<QPushButton *>(QStringLiteral("connectButton"))->text(),
             QStringLiteral("Disconnect")); // still open
    bar.setCanCondition(lk::transport::CanBusCondition::Good, {});
    QCOMPARE(bar.stateText(), QStringLiteral("Connected: socketcan:can0 @ 1000000 bit/s"));
    // A condition belongs to its link: a closed link forgets it.
    bar.setCanCondition(lk::transport::CanBusCondition(condition), fix);
    s.state = lk::transport::Transport::State::Closed;
    bar.setConnectionStatus(s);
    s.state = lk::transport::Transport::State::Open;
    bar.setConnectionStatus(s);
    QVERIFY(!bar.stateText().contains(said));
}

// On a narrow screen the state text is cut (the status bar says it whole), not the controls
// nor the emergency stop beside the bar: it asks for its whole width but accepts a few
// characters, and the whole text is then the first line of its tooltip.
void tst_ConnectionBar::stateGivesUpWidthFirst()
{
    ConnectionBar bar;
    fakeCan(bar);
    lk::bus::ConnectionStatus s = openCan();
    bar.setConnectionStatus(s);
    bar.setCanCondition(lk::transport::CanBusCondition::NoAcknowledge,
                        QStringLiteral("Check the drives' power."));
    auto *state = bar.findChild<lk::ui::ElidedLabel *>(QStringLiteral("connectionState"));
    QVERIFY(state);
    QCOMPARE(state->fullText(), bar.stateText());
    const int whole = state->fontMetrics().horizontalAdvance(bar.stateText());
    QVERIFY2(bar.minimumSizeHint().width() < bar.sizeHint().width() - whole / 2,
             qPrintable(QStringLiteral("minimum %1, hint %2")
                            .arg(bar.minimumSizeHint().width())
                            .arg(bar.sizeHint().width())));
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    bar.resize(bar.sizeHint());
    QTRY_VERIFY(!state->isElided());
    QVERIFY(!state->toolTip().startsWith(bar.stateText())); // the detail alone
    bar.resize(bar.minimumSizeHint());
    QTRY_VERIFY(state->isElided());
    QVERIFY(state->text().endsWith(QChar(0x2026)));
    QVERIFY2(state->toolTip().startsWith(bar.stateText() + QLatin1Char('\n')),
             qPrintable(state->toolTip()));
    QVERIFY(state->toolTip().contains(QStringLiteral("Check the drives' power.")));
}

QTEST_MAIN(tst_ConnectionBar)
#include "tst_connectionbar.moc"
