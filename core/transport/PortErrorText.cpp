#include "PortErrorText.h"

#include <QtCore/QCoreApplication>

namespace lk::transport {

namespace {
QString baseText(TransportError::Kind kind, const QString &port, int baud)
{
    using Kind = TransportError::Kind;
    switch (kind) {
    case Kind::None:
        return {};
    case Kind::NoSuchPort:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "No serial port %1. The device does not exist: is the adapter "
                   "plugged in?")
            .arg(port);
    case Kind::PermissionDenied:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "No permission to open %1. Add your user to the serial port group "
                   "(`sudo usermod -aG dialout $USER` on Debian/Ubuntu, group `uucp` on Arch), "
                   "then log out and in again.")
            .arg(port);
    case Kind::PortBusy:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "%1 is in use by another program (a terminal, another lkstudio, "
                   "ModemManager?). Close it and try again; `fuser %1` shows who "
                   "holds it.")
            .arg(port);
    case Kind::Unplugged:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "The serial adapter %1 was disconnected (unplugged or reset). "
                   "Plug it back in and reconnect.")
            .arg(port);
    case Kind::BadSettings:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "%1 refused %2 baud 8N1. Try another baud or another adapter.")
            .arg(port)
            .arg(baud);
    case Kind::NotSerialDevice:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "%1 is not a serial device. Give the adapter's port, e.g. /dev/ttyUSB0; "
                   "`ls /dev/serial/by-id/` lists the adapters plugged in.")
            .arg(port);
    case Kind::IoError:
        return QCoreApplication::translate(
                   "lk::transport::PortErrorText",
                   "Serial port %1 failed (input/output error). Check the cable and the adapter.")
            .arg(port);
    case Kind::CanPluginMissing:
    case Kind::CanBusOff:
    case Kind::CanErrorPassive:
    case Kind::CanNoAcknowledge:
        return {}; // a CAN link's words are CanTransport's: no serial port has these
    }
    return {};
}
} // namespace

TransportError portError(TransportError::Kind kind, const QString &port, int baud,
                         const QString &detail)
{
    TransportError e;
    e.kind = kind;
    e.message = baseText(kind, port, baud);
    if (kind != TransportError::Kind::None && !detail.isEmpty())
        e.message += QStringLiteral(" (%1)").arg(detail);
    return e;
}

} // namespace lk::transport
