#pragma once

#include "CanBusCondition.h"
#include "Transport.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtSerialBus/QCanBusDevice>
#include <QtSerialBus/QCanBusFrame>

#include <functional>
#include <memory>
#include <optional>

namespace lk::transport {

/// How to open a CAN interface through Qt SerialBus: a plain value.
struct CanSettings {
    QString plugin = QStringLiteral("socketcan"); ///< a key of QCanBus::plugins()
    /// "can0"; for virtualcan also "tcp://127.0.0.1:35468/can0" (a server of one's own).
    QString interfaceName = QStringLiteral("can0");
    int bitRate = 1000000; ///< the drives' bit rate (LK default 1 Mbit/s)
    /// Ask Qt to set the bit rate (socketcan: needs libsocketcan and the right to do it).
    bool setBitRate = true;
};

/// A Transport over a QCanBusDevice: moves CanRecords (protocol/CanRecord.h) both ways, so
/// that the engine keeps moving bytes and the codec decides what they mean. Construct it on
/// the thread that uses it. Error frames arrive as records with the Error flag and change
/// condition(); a failed write is reported once and keeps the link open. Only the device
/// itself going away (unplugged interface, virtualcan server gone) makes it Disconnected.
class CanTransport : public Transport {
    Q_OBJECT
public:
    /// Makes the device (QCanBus::createDevice in production; a test double in tests).
    using DeviceFactory =
        std::function<std::unique_ptr<QCanBusDevice>(const CanSettings &, QString *error)>;

    explicit CanTransport(const CanSettings &settings, QObject *parent = nullptr);
    CanTransport(const CanSettings &settings, DeviceFactory makeDevice, QObject *parent = nullptr);
    ~CanTransport() override;

    bool open() override;
    void close() override;
    /// Whole CanRecords; a trailing partial record is dropped (and logged).
    void write(const QByteArray &bytes) override;
    State state() const override { return m_state; }
    int baud() const override { return m_settings.bitRate; } ///< the bit rate
    QString description() const override;
    protocol::Link link() const override { return protocol::Link::Can; }

    const CanSettings &settings() const { return m_settings; }
    CanBusCondition condition() const { return m_condition; }
    /// Frames that could not be handed to the device since open().
    quint64 failedWrites() const { return m_failedWrites; }

    /// The condition an error frame reports, or nullopt when it does not change it (a single
    /// bus error, lost arbitration).
    static std::optional<CanBusCondition> conditionOf(const QCanBusFrame &errorFrame);
    /// The CAN plugins Qt finds on this system ("socketcan", "virtualcan", ...).
    static QStringList plugins();
    /// The interfaces `plugin` reports ("can0", "vcan0", ...).
    static QStringList interfaces(const QString &plugin);
    /// A transport factory for BusSession: a new CanTransport per open, at `bitRate`.
    static std::function<std::unique_ptr<Transport>(int bitRate)> factory(CanSettings settings);

private:
    void onFramesReceived();
    void onDeviceError(QCanBusDevice::CanBusError error);
    void onDeviceState(QCanBusDevice::CanBusDeviceState state);
    void sendNow(const QCanBusFrame &frame);
    void setCondition(CanBusCondition condition);
    void setState(State state);
    void report(TransportError::Kind kind, const QString &message);
    void lost(const QString &detail);
    void reportOpenFailure(const QString &detail);
    QString bringUpCommand() const;
    QString name() const;

    CanSettings m_settings;
    DeviceFactory m_makeDevice;
    std::unique_ptr<QCanBusDevice> m_device;
    State m_state = State::Closed;
    CanBusCondition m_condition = CanBusCondition::Good;
    QList<QCanBusFrame> m_pending; ///< written while the device was still connecting
    quint64 m_failedWrites = 0;
    bool m_writeErrorReported = false; ///< one report until a frame gets through again
    bool m_lostReported = false;
};

} // namespace lk::transport
