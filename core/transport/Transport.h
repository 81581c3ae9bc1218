#pragma once

#include "CanBusCondition.h"

#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QObject>
#include <QtCore/QString>

namespace lk::transport {

/// Why a transport failed, in terms a technician can act on.
struct TransportError {
    enum class Kind {
        None,
        NoSuchPort,       ///< the device does not exist (unplugged, wrong name)
        PermissionDenied, ///< not in the dialout/uucp group
        PortBusy,         ///< another program holds the port
        Unplugged,        ///< the device vanished while open
        BadSettings,      ///< baud or framing refused by the driver
        NotSerialDevice,  ///< the path is a file, a directory or a device that is no tty
        IoError,          ///< any other read/write failure
        CanPluginMissing, ///< Qt has no CAN plugin of that name (CanTransport)
        CanBusOff,        ///< the CAN controller stopped sending after too many errors
        CanErrorPassive,  ///< many frames fail on the CAN bus; the link is still open
        CanNoAcknowledge, ///< nobody acknowledged a CAN frame: no drive, or another bit rate
    };
    Kind kind = Kind::None;
    /// A complete sentence with the fix where there is one, translated where it is made:
    /// every surface (lkctl, the GUI's banner) shows it as it is, none words it again.
    QString message;
};

/// Moves bytes to and from one bus (RS485, or CAN as records) and reports its connection state;
/// nothing more. Framing, matching and timing live above it (BusWorker). An implementation lives on
/// the bus thread and is used only from there.
class Transport : public QObject {
    Q_OBJECT
public:
    enum class State { Closed, Open, Disconnected };
    Q_ENUM(State)

    using QObject::QObject;
    ~Transport() override = default;

    /// Open the link. On failure returns false, stays Closed and emits errorOccurred.
    virtual bool open() = 0;
    /// Listen only: open() opens for reading alone where the medium allows it, and write()
    /// drops every byte and counts it (refusedWrites()). Set before open(); the owner
    /// (TransportLink) sets it on each transport the factory makes.
    void setReadOnly(bool readOnly) { m_readOnly = readOnly; }
    bool isReadOnly() const { return m_readOnly; }
    /// Bytes write() dropped because the transport is read-only (0 in a listen-only session
    /// that works as it should: the bus refuses before anything reaches a transport).
    quint64 refusedWrites() const { return m_refusedWrites; }
    virtual void close() = 0;
    /// Queue bytes for sending; a closed or disconnected transport drops them.
    virtual void write(const QByteArray &bytes) = 0;
    virtual State state() const = 0;
    /// Bits per second on the wire (used for timeouts and the bus limit).
    virtual int baud() const = 0;
    /// "/dev/ttyUSB0 @ 115200", "Simulated bus (3 drives)".
    virtual QString description() const = 0;
    /// What the bytes are: an RS485 byte stream, or CanRecords (protocol/CanRecord.h). The
    /// engine picks its frame parser, codec layouts and timing from it.
    virtual protocol::Link link() const { return protocol::Link::Rs485; }

protected:
    /// For write(): true when the transport is read-only, after counting and logging the
    /// bytes it then drops.
    bool refuseWriteIfReadOnly(const QByteArray &bytes);

signals:
    void bytesReceived(const QByteArray &bytes);
    void stateChanged(lk::transport::Transport::State state);
    /// A link lost while open says why first (Unplugged, IoError), then goes Disconnected:
    /// the state's reason can name the cause.
    void errorOccurred(const lk::transport::TransportError &error);
    /// A CAN link's bus condition changed (only a CAN transport emits it). It is declared here
    /// so that a decorator (the black-box recorder) forwards it like any other signal and the
    /// engine sees bus-off and no-ACK through it.
    void canConditionChanged(lk::transport::CanBusCondition condition);

private:
    bool m_readOnly = false;
    quint64 m_refusedWrites = 0;
};

} // namespace lk::transport

Q_DECLARE_METATYPE(lk::transport::TransportError)
