#include <panels/ConnectionBar.h>

#include <QtTest/QtTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
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

QTEST_MAIN(tst_ConnectionBar)
#include "tst_connectionbar.moc"
