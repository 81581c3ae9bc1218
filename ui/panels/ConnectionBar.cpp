#include "ConnectionBar.h"

#include "ElidedLabel.h"
#include "Format.h"
#include "PortAccessDialog.h"
#include "StatusColors.h"
#include "ThemedIcon.h"

#include <bus/BusTiming.h>

#include <QtCore/QTimer>
#include <QtGui/QIcon>
#include <QtSerialPort/QSerialPortInfo>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QToolButton>

namespace lk::ui {

namespace {
constexpr int kRefreshMs = 1000;
constexpr int kKindRole = Qt::UserRole + 1; // ConnectionChoice::Kind as int
constexpr int kPortRole = Qt::UserRole + 2; // device location
} // namespace

QString PortEntry::label() const
{
    QString text = name;
    const QString what = description.isEmpty() ? manufacturer : description;
    if (!what.isEmpty())
        text += QStringLiteral(" \u2013 ") + what;
    if (vendorId && productId) {
        text += QStringLiteral(" (%1:%2)")
                    .arg(*vendorId, 4, 16, QLatin1Char('0'))
                    .arg(*productId, 4, 16, QLatin1Char('0'));
    }
    return text;
}

ConnectionBar::ConnectionBar(QWidget *parent)
    : QWidget(parent), m_canPlugins(&transport::CanTransport::plugins),
      m_canInterfaces(&transport::CanTransport::interfaces), m_lister(&systemPorts)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);

    m_link = new QComboBox(this);
    m_link->setObjectName(QStringLiteral("linkCombo"));
    m_link->addItem(tr("RS485"), false);
    m_link->addItem(tr("CAN"), true);
    m_link->setToolTip(tr("How the drives are wired to this computer: a USB-RS485 adapter, or a "
                          "CAN adapter (candleLight/gs_usb, PCAN-USB, CANable; see README, "
                          "\"Drives on CAN\")"));
    m_rs485Row = buildRs485Row();
    m_canRow = buildCanRow();

    m_listenOnly = new QCheckBox(tr("Listen only"), this);
    m_listenOnly->setObjectName(QStringLiteral("listenOnly"));
    m_listenOnly->setToolTip(
        tr("Watch a bus that another controller runs: the port opens read-only and this tool "
           "transmits nothing, not even an emergency stop. Use an adapter with automatic "
           "direction control (see README, \"Diagnosing a running machine\")."));

    m_connect = new QPushButton(this);
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_autoReconnect = new QCheckBox(tr("Auto-reconnect"), this);
    m_autoReconnect->setObjectName(QStringLiteral("autoReconnect"));
    m_autoReconnect->setChecked(true);
    m_autoReconnect->setToolTip(tr("Reopen the port by itself when the adapter comes back"));
    m_stateDot = new QLabel(this);
    m_stateDot->setObjectName(QStringLiteral("connectionStateDot"));
    m_state = new ElidedLabel(this);
    m_state->setObjectName(QStringLiteral("connectionState"));
    m_accessHelp = new QToolButton(this);
    m_accessHelp->setObjectName(QStringLiteral("accessHelp"));
    m_accessHelp->setText(tr("Fix permission\u2026"));
    m_accessHelp->setToolTip(tr("The port was refused: show the command that gives you access"));
    m_accessHelp->setVisible(false);
    connect(m_accessHelp, &QToolButton::clicked, this, &ConnectionBar::showAccessHelp);
    m_takeOver = new QPushButton(tr("Take over the bus\u2026"), this);
    m_takeOver->setObjectName(QStringLiteral("takeOver"));
    m_takeOver->setToolTip(tr("Reopen the port read-write and become the bus master (asks first)"));
    m_takeOver->setVisible(false);
    connect(m_takeOver, &QPushButton::clicked, this, &ConnectionBar::takeOverRequested);

    layout->addWidget(m_link);
    layout->addWidget(m_rs485Row, 1);
    layout->addWidget(m_canRow, 1);
    layout->addWidget(m_listenOnly);
    layout->addWidget(m_connect);
    layout->addWidget(m_autoReconnect);
    layout->addWidget(m_accessHelp);
    layout->addWidget(m_takeOver);
    layout->addWidget(m_stateDot);
    // No stretch of its own: the state takes the width of its text while there is room (the
    // stretch after it takes the rest), and gives it up before any control does when there is
    // not.
    layout->addWidget(m_state);
    layout->addStretch(1);

    m_refresh = new QTimer(this);
    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, &ConnectionBar::refreshPorts);
    m_refresh->start();
    connect(m_connect, &QPushButton::clicked, this, &ConnectionBar::onConnectClicked);
    connect(m_autoReconnect, &QCheckBox::toggled, this, [this] { emit choiceChanged(choice()); });
    connect(m_listenOnly, &QCheckBox::toggled, this, [this] { emit choiceChanged(choice()); });
    connect(m_link, qOverload<int>(&QComboBox::activated), this, [this] {
        showLinkWidgets();
        emit choiceChanged(choice());
    });

    m_ports = m_lister();
    rebuildPortItems();
    rebuildCanItems();
    showLinkWidgets();
    updateState();
}

QWidget *ConnectionBar::buildRs485Row()
{
    auto *row = new QWidget(this);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    m_port = new QComboBox(row);
    m_port->setObjectName(QStringLiteral("portCombo"));
    m_port->setEditable(true); // a pseudo-terminal from lksim is typed in, it is never listed
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(28);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setToolTip(tr("Serial port of the USB-RS485 adapter, or the built-in simulated bus. "
                          "You can also type a device path, e.g. a pseudo-terminal from lksim."));

    m_baud = new QComboBox(row);
    m_baud->setObjectName(QStringLiteral("baudCombo"));
    for (int baud : bus::BusTiming::standardBauds())
        m_baud->addItem(QString::number(baud), baud);
    m_baud->setCurrentIndex(m_baud->findData(bus::BusTiming::kDefaultBaud));
    m_baud->setToolTip(tr("Baud rate set on the drives (DIP switches or the vendor's tool)"));
    layout->addWidget(new QLabel(tr("Port:"), row));
    layout->addWidget(m_port, 1);
    layout->addWidget(new QLabel(tr("Baud:"), row));
    layout->addWidget(m_baud);
    return row;
}

QWidget *ConnectionBar::buildCanRow()
{
    auto *row = new QWidget(this);
    row->setObjectName(QStringLiteral("canRow"));
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    m_canPlugin = new QComboBox(row);
    m_canPlugin->setObjectName(QStringLiteral("canPluginCombo"));
    m_canPlugin->setToolTip(tr("The Qt SerialBus plugin: socketcan for every adapter the Linux "
                               "kernel knows (candleLight/gs_usb, PCAN-USB, CANable through "
                               "slcand, vcan), virtualcan for tests without hardware"));
    m_canInterface = new QComboBox(row);
    m_canInterface->setObjectName(QStringLiteral("canInterfaceCombo"));
    m_canInterface->setEditable(true); // an interface not listed yet can be typed in
    m_canInterface->setInsertPolicy(QComboBox::NoInsert);
    m_canInterface->setMinimumContentsLength(10);
    m_canInterface->setToolTip(tr("The CAN interface the plugin reports (can0, slcan0, vcan0); "
                                  "`ip link show` lists them"));
    m_bitRate = new QComboBox(row);
    m_bitRate->setObjectName(QStringLiteral("bitRateCombo"));
    for (int rate : ConnectionChoice::canBitRates())
        m_bitRate->addItem(Format::bitRate(rate), rate);
    m_bitRate->setCurrentIndex(m_bitRate->findData(ConnectionChoice::kDefaultBitRate));
    m_bitRate->setToolTip(tr("The drives' CAN bit rate (1 Mbit/s unless changed with the vendor's "
                             "tool over RS485). lkstudio sets it on the interface where the "
                             "system allows; otherwise it shows the command to run as root."));
    layout->addWidget(new QLabel(tr("Plugin:"), row));
    layout->addWidget(m_canPlugin);
    layout->addWidget(new QLabel(tr("Interface:"), row));
    layout->addWidget(m_canInterface, 1);
    layout->addWidget(new QLabel(tr("Bit rate:"), row));
    layout->addWidget(m_bitRate);
    connect(m_canPlugin, qOverload<int>(&QComboBox::activated), this, [this] {
        rebuildCanItems();
        emit choiceChanged(choice());
    });
    return row;
}

void ConnectionBar::setCanListers(CanPluginLister plugins, CanInterfaceLister interfaces)
{
    m_canPlugins = std::move(plugins);
    m_canInterfaces = std::move(interfaces);
    rebuildCanItems();
}

void ConnectionBar::rebuildCanItems()
{
    const ConnectionChoice keep = choice();
    const QStringList plugins = m_canPlugins();
    if (plugins != m_pluginList || m_canPlugin->count() == 0) {
        m_pluginList = plugins;
        const QSignalBlocker block(m_canPlugin);
        m_canPlugin->clear();
        // First, as on RS485: the built-in simulated CAN bus (old and V2.36 drives).
        m_canPlugin->addItem(ThemedIcon::get(QStringLiteral(":/icons/simulator.svg")),
                             tr("Simulator (built-in)"));
        m_canPlugin->setItemData(0, static_cast<int>(ConnectionChoice::Kind::Simulator), kKindRole);
        for (const QString &plugin : plugins) {
            m_canPlugin->addItem(plugin);
            m_canPlugin->setItemData(m_canPlugin->count() - 1,
                                     static_cast<int>(ConnectionChoice::Kind::Can), kKindRole);
        }
    }
    const QStringList interfaces =
        keep.isSimulator() && keep.simulatedCan ? QStringList() : m_canInterfaces(keep.canPlugin);
    if (interfaces != m_interfaceList) {
        m_interfaceList = interfaces;
        const QSignalBlocker block(m_canInterface);
        m_canInterface->clear();
        m_canInterface->addItems(interfaces);
    }
    setChoice(keep);
}

void ConnectionBar::showLinkWidgets()
{
    const bool can = m_link->currentData().toBool();
    m_rs485Row->setVisible(!can);
    m_canRow->setVisible(can);
}

void ConnectionBar::setPortLister(PortLister lister)
{
    m_lister = std::move(lister);
    refreshPorts();
}

QList<PortEntry> ConnectionBar::systemPorts()
{
    QList<PortEntry> out;
    const auto infos = QSerialPortInfo::availablePorts();
    for (const auto &info : infos) {
        PortEntry e;
        e.name = info.portName();
        e.location = info.systemLocation();
        e.description = info.description();
        e.manufacturer = info.manufacturer();
        if (info.hasVendorIdentifier())
            e.vendorId = info.vendorIdentifier();
        if (info.hasProductIdentifier())
            e.productId = info.productIdentifier();
        out << e;
    }
    return out;
}

void ConnectionBar::refreshPorts()
{
    if (m_link->currentData().toBool()) {
        rebuildCanItems(); // on CAN the interfaces are what comes and goes
        return;
    }
    const QList<PortEntry> now = m_lister();
    if (now == m_ports)
        return;
    m_ports = now;
    rebuildPortItems();
    emit portsChanged(m_ports);
}

void ConnectionBar::rebuildPortItems()
{
    // Keep what the user chose (or typed) across the rebuild.
    const ConnectionChoice keep = choice();
    const QSignalBlocker block(m_port);
    m_port->clear();
    m_port->addItem(ThemedIcon::get(QStringLiteral(":/icons/simulator.svg")),
                    tr("Simulator (built-in)"));
    m_port->setItemData(0, static_cast<int>(ConnectionChoice::Kind::Simulator), kKindRole);
    for (const auto &p : m_ports) {
        m_port->addItem(ThemedIcon::get(QStringLiteral(":/icons/port.svg")), p.label());
        const int i = m_port->count() - 1;
        m_port->setItemData(i, static_cast<int>(ConnectionChoice::Kind::Serial), kKindRole);
        m_port->setItemData(i, p.location.isEmpty() ? p.name : p.location, kPortRole);
    }
    setChoice(keep);
}

ConnectionChoice ConnectionBar::choice() const
{
    ConnectionChoice c;
    c.baud = m_baud->currentData().toInt();
    c.autoReconnect = m_autoReconnect->isChecked();
    c.listenOnly = m_listenOnly->isChecked();
    if (!m_canPlugin->currentText().isEmpty() && !canSimulatorChosen())
        c.canPlugin = m_canPlugin->currentText();
    c.canInterface = m_canInterface->currentText().trimmed();
    c.bitRate = m_bitRate->currentData().toInt();
    const int i = m_port->currentIndex();
    const QString text = m_port->currentText().trimmed();
    if (i >= 0 && text == m_port->itemText(i)) {
        c.kind = static_cast<ConnectionChoice::Kind>(m_port->itemData(i, kKindRole).toInt());
        c.port = m_port->itemData(i, kPortRole).toString();
    } else {
        c.kind =
            text.isEmpty() ? ConnectionChoice::Kind::Simulator : ConnectionChoice::Kind::Serial;
        c.port = text;
    }
    if (m_link->currentData().toBool()) {
        // The serial port stays chosen for RS485; on CAN the plugin's first entry is the
        // built-in simulated bus.
        c.simulatedCan = canSimulatorChosen();
        c.kind = c.simulatedCan ? ConnectionChoice::Kind::Simulator : ConnectionChoice::Kind::Can;
    }
    return c;
}

void ConnectionBar::setChoice(const ConnectionChoice &c)
{
    const int baud = m_baud->findData(c.baud);
    if (baud >= 0)
        m_baud->setCurrentIndex(baud);
    m_autoReconnect->setChecked(c.autoReconnect);
    m_listenOnly->setChecked(c.listenOnly);
    setCanChoice(c);
    // On CAN the RS485 side keeps its port for a switch back: a port named is a serial port.
    if ((c.isSimulator() && !c.simulatedCan) ||
        (c.link() == protocol::Link::Can && c.port.isEmpty())) {
        m_port->setCurrentIndex(0);
        return;
    }
    for (int i = 1; i < m_port->count(); ++i) {
        const QString loc = m_port->itemData(i, kPortRole).toString();
        if (loc == c.port || loc.endsWith(QLatin1Char('/') + c.port)) {
            m_port->setCurrentIndex(i);
            return;
        }
    }
    // Not listed (a pty, or an adapter that is away just now): keep the name as typed.
    m_port->setCurrentIndex(-1);
    m_port->setEditText(c.port);
}

bool ConnectionBar::canSimulatorChosen() const
{
    return m_canPlugin->currentIndex() >= 0 &&
           m_canPlugin->currentData(kKindRole).toInt() ==
               static_cast<int>(ConnectionChoice::Kind::Simulator);
}

void ConnectionBar::setCanChoice(const ConnectionChoice &c)
{
    const bool onCan = c.link() == protocol::Link::Can;
    m_link->setCurrentIndex(onCan ? 1 : 0);
    showLinkWidgets();
    const int rate = m_bitRate->findData(c.bitRate);
    if (rate >= 0)
        m_bitRate->setCurrentIndex(rate);
    if (onCan && c.isSimulator()) {
        m_canPlugin->setCurrentIndex(0);
        m_canInterface->setEnabled(false); // the simulated bus has no interface
        return;
    }
    m_canInterface->setEnabled(m_status.state == transport::Transport::State::Closed);
    int plugin = c.canPlugin.isEmpty() ? -1 : m_canPlugin->findText(c.canPlugin);
    if (plugin == 0)
        plugin = -1; // a plugin named like the simulator's entry is no plugin of Qt's
    if (plugin < 0 && !c.canPlugin.isEmpty()) {
        // Remembered but not found now (its library is gone): keep it, opening says why.
        m_canPlugin->addItem(c.canPlugin);
        m_canPlugin->setItemData(m_canPlugin->count() - 1,
                                 static_cast<int>(ConnectionChoice::Kind::Can), kKindRole);
        plugin = m_canPlugin->count() - 1;
    }
    m_canPlugin->setCurrentIndex(plugin);
    const int iface = m_canInterface->findText(c.canInterface);
    m_canInterface->setCurrentIndex(iface);
    if (iface < 0)
        m_canInterface->setEditText(c.canInterface); // not up yet: keep the name as typed
}

void ConnectionBar::setCanCondition(transport::CanBusCondition condition, const QString &message)
{
    m_canCondition = condition;
    m_canMessage = condition == transport::CanBusCondition::Good ? QString() : message;
    updateState();
}

void ConnectionBar::setConnectionStatus(const bus::ConnectionStatus &status)
{
    m_status = status;
    if (!status.isOpen()) { // a new link starts with a good bus until its controller says
        m_canCondition = transport::CanBusCondition::Good;
        m_canMessage.clear();
    }
    if (status.isOpen()) {
        m_deniedPort.clear(); // the port opened after all: the advice is done
        m_accessHelp->setVisible(false);
    }
    // A baud sweep may leave the port at another baud than the one picked: show the truth.
    const int baud = m_baud->findData(status.baud);
    if (status.isOpen() && baud >= 0)
        m_baud->setCurrentIndex(baud);
    updateState();
}

void ConnectionBar::showPortError(const transport::TransportError &error)
{
    if (error.kind != transport::TransportError::Kind::PermissionDenied)
        return;
    m_deniedPort = choice().port;
    m_accessHelp->setVisible(true);
}

void ConnectionBar::showAccessHelp()
{
    auto *dialog = new PortAccessDialog(m_deniedPort, SerialGroupAdvice::forThisSystem(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

void ConnectionBar::onConnectClicked()
{
    if (m_status.state == transport::Transport::State::Closed) {
        const ConnectionChoice c = choice();
        emit choiceChanged(c);
        emit connectRequested(c);
    } else {
        emit disconnectRequested();
    }
}

void ConnectionBar::updateState()
{
    using S = transport::Transport::State;
    const bool closed = m_status.state == S::Closed;
    m_link->setEnabled(closed);
    m_port->setEnabled(closed);
    m_baud->setEnabled(closed);
    m_canPlugin->setEnabled(closed);
    m_canInterface->setEnabled(closed && !canSimulatorChosen());
    m_bitRate->setEnabled(closed);
    m_listenOnly->setEnabled(closed);
    // Taking over is for a link that is up and listening; a closed one simply reconnects.
    m_takeOver->setVisible(m_status.state == S::Open && !m_status.canTransmit);
    // Listing ports asks udev and costs milliseconds each time; while the link is open the
    // list cannot be used (the combo is disabled), so it rests until the link is not open.
    if (m_status.state == S::Open) {
        m_refresh->stop();
    } else if (!m_refresh->isActive()) {
        m_refresh->start();
        refreshPorts();
    }
    m_connect->setText(closed ? tr("Connect") : tr("Disconnect"));
    m_connect->setIcon(ThemedIcon::get(closed ? QStringLiteral(":/icons/connect.svg")
                                              : QStringLiteral(":/icons/disconnect.svg")));
    StatusColors::Role role = StatusColors::Role::Muted;
    if (m_status.state == S::Open)
        role = m_status.canTransmit ? StatusColors::Role::Ok : StatusColors::Role::Info;
    else if (m_status.state == S::Disconnected)
        role = StatusColors::Role::Error;
    if (m_status.isOpen() && Format::canConditionIsFault(m_canCondition))
        role = StatusColors::Role::Warning; // open, but the bus does not carry frames well
    const QString color = StatusColors::text(role, StatusColors::current()).name();
    m_stateDot->setText(QStringLiteral("<span style=\"color:%1\">\u25cf</span>").arg(color));
    m_state->setFullText(stateText());
    m_state->setDetail(
        m_canMessage.isEmpty()
            ? Format::connectionDetail(m_status)
            : QStringLiteral("%1\n%2").arg(Format::connectionDetail(m_status), m_canMessage));
}

QString ConnectionBar::stateText() const
{
    return Format::linkState(m_status, m_canCondition);
}

void ConnectionBar::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        updateState(); // the state dot's colour follows a light/dark switch
}

} // namespace lk::ui
