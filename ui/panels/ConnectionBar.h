#pragma once

#include "ConnectionChoice.h"

#include <bus/ConnectionStatus.h>
#include <transport/CanTransport.h>
#include <transport/Transport.h>

#include <QtCore/QList>
#include <QtWidgets/QWidget>

#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QTimer;
class QToolButton;

namespace lk::ui {

class ElidedLabel;

/// One serial port as the connection bar lists it.
struct PortEntry {
    QString name;     ///< "ttyUSB0"
    QString location; ///< "/dev/ttyUSB0"
    QString description;
    QString manufacturer;
    std::optional<quint16> vendorId, productId;
    bool operator==(const PortEntry &o) const
    {
        return name == o.name && location == o.location && description == o.description &&
               vendorId == o.vendorId && productId == o.productId;
    }
    /// "ttyUSB0 - FT232R USB UART (0403:6001)"
    QString label() const;
};

/// Top bar: the link (RS485 or CAN); for RS485 the port (serial ports with USB description and
/// VID:PID, or the built-in simulator) and baud, for CAN the Qt SerialBus plugin (or the
/// built-in simulator with CAN drives), its interface and the bit rate; listen only,
/// connect/disconnect, auto-reconnect, and the link state (on CAN with the bus condition: bus-off,
/// error-passive, no acknowledgement); while a link listens, "Take over the bus". The port and
/// interface lists refresh themselves about once a second so that adapters coming and going show up
/// without a click.
class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    using PortLister = std::function<QList<PortEntry>()>;
    /// The CAN plugins Qt finds, and the interfaces of one of them (tests replace them).
    using CanPluginLister = std::function<QStringList()>;
    using CanInterfaceLister = std::function<QStringList(const QString &plugin)>;

    explicit ConnectionBar(QWidget *parent = nullptr);

    /// Replace how ports are listed (tests); the default asks QSerialPortInfo.
    void setPortLister(PortLister lister);
    static QList<PortEntry> systemPorts();
    QList<PortEntry> ports() const { return m_ports; }
    /// Replace how CAN plugins and interfaces are listed; the default asks QCanBus
    /// (transport::CanTransport::plugins() and interfaces()).
    void setCanListers(CanPluginLister plugins, CanInterfaceLister interfaces);

    ConnectionChoice choice() const;
    void setChoice(const ConnectionChoice &choice);

    /// Show the link state; the port and baud cannot change while a link is open.
    void setConnectionStatus(const bus::ConnectionStatus &status);
    /// The CAN bus condition of the open link and the transport's sentence about it (with its
    /// fix), shown in the state; Good clears it.
    void setCanCondition(transport::CanBusCondition condition, const QString &message);
    /// The button that explains how to get permission for the port (shown after a refusal).
    QToolButton *accessHelpButton() const { return m_accessHelp; }
    /// "Take over the bus", shown while the open link listens only.
    QPushButton *takeOverButton() const { return m_takeOver; }
    /// The link state as the bar shows it (tests).
    QString stateText() const;

public slots:
    void refreshPorts();
    /// A port failed to open: for a permission refusal, offer the command that fixes it.
    void showPortError(const lk::transport::TransportError &error);
    /// Show how to get permission for the port that was refused (PortAccessDialog).
    void showAccessHelp();

signals:
    void connectRequested(const lk::ui::ConnectionChoice &choice);
    void disconnectRequested();
    /// The user asked to take over a bus the link listens to (not yet confirmed).
    void takeOverRequested();
    void choiceChanged(const lk::ui::ConnectionChoice &choice);
    /// The set of serial ports changed (an adapter came or went).
    void portsChanged(const QList<lk::ui::PortEntry> &ports);

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuildPortItems();
    void rebuildCanItems();
    void showLinkWidgets();
    void setCanChoice(const ConnectionChoice &choice);
    /// The CAN plugin list's first entry, the built-in simulated CAN bus, is chosen.
    bool canSimulatorChosen() const;
    QWidget *buildRs485Row();
    QWidget *buildCanRow();
    void onConnectClicked();
    void updateState();

    QComboBox *m_link = nullptr;
    QWidget *m_rs485Row = nullptr;
    QWidget *m_canRow = nullptr;
    QComboBox *m_canPlugin = nullptr;
    QComboBox *m_canInterface = nullptr;
    QComboBox *m_bitRate = nullptr;
    CanPluginLister m_canPlugins;
    CanInterfaceLister m_canInterfaces;
    QStringList m_pluginList;    ///< as last listed
    QStringList m_interfaceList; ///< of the chosen plugin, as last listed
    transport::CanBusCondition m_canCondition = transport::CanBusCondition::Good;
    QString m_canMessage;
    QComboBox *m_port = nullptr;
    QComboBox *m_baud = nullptr;
    QPushButton *m_connect = nullptr;
    QCheckBox *m_autoReconnect = nullptr;
    QCheckBox *m_listenOnly = nullptr;
    QPushButton *m_takeOver = nullptr;
    QLabel *m_stateDot = nullptr;   ///< the state's colour, always shown
    ElidedLabel *m_state = nullptr; ///< gives up width first; the status bar says it whole
    QToolButton *m_accessHelp = nullptr;
    QString m_deniedPort; ///< the port refused for lack of permission; empty: none
    QTimer *m_refresh = nullptr;
    PortLister m_lister;
    QList<PortEntry> m_ports;
    bus::ConnectionStatus m_status;
};

} // namespace lk::ui
