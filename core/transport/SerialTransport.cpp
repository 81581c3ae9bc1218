#include "SerialTransport.h"

#include <QtCore/QCoreApplication>

#include "PortErrorText.h"

#include <QtCore/QDebug>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QLoggingCategory>
#include <QtCore/QStringList>
#include <QtSerialPort/QSerialPortInfo>

#ifdef Q_OS_LINUX
#include <linux/serial.h>
#include <sys/ioctl.h>
#endif
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lk::transport {

namespace {
Q_LOGGING_CATEGORY(lcSerial, "lk.transport.serial")

QString availablePortsText()
{
    QStringList names;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
        names << info.systemLocation();
    return names.isEmpty()
               ? QCoreApplication::translate("lk::transport::SerialTransport",
                                             "no serial ports found")
               : QCoreApplication::translate("lk::transport::SerialTransport", "ports found: %1")
                     .arg(names.join(QStringLiteral(", ")));
}

/// What `path` is when it is not a terminal ("a regular file"...); empty when it is one (a
/// serial adapter, or a pseudo-terminal such as lksim's) or cannot be told. Asked only after
/// the port failed to open: opening a working adapter just to ask could toggle its lines.
QString nonTerminalKind(const QString &path)
{
    const auto say = [](const char *text) {
        return QCoreApplication::translate("lk::transport::SerialTransport", text);
    };
    const QByteArray name = QFile::encodeName(path);
    struct stat st {};
    if (::stat(name.constData(), &st) != 0)
        return {};
    if (S_ISREG(st.st_mode))
        return say(QT_TRANSLATE_NOOP("lk::transport::SerialTransport", "a regular file"));
    if (S_ISDIR(st.st_mode))
        return say(QT_TRANSLATE_NOOP("lk::transport::SerialTransport", "a directory"));
    if (!S_ISCHR(st.st_mode))
        return say(
            QT_TRANSLATE_NOOP("lk::transport::SerialTransport", "a pipe, socket or block device"));
    const int fd = ::open(name.constData(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return {};
    const bool terminal = ::isatty(fd) == 1;
    ::close(fd);
    return terminal ? QString()
                    : say(QT_TRANSLATE_NOOP("lk::transport::SerialTransport",
                                            "a device that is not a terminal"));
}
} // namespace

SerialTransport::SerialTransport(const SerialSettings &settings, QObject *parent)
    : Transport(parent), m_settings(settings), m_path(systemPath(settings.portName)),
      m_port(new QSerialPort(this))
{
    connect(m_port, &QSerialPort::readyRead, this, &SerialTransport::onReadyRead);
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onPortError);
}

SerialTransport::~SerialTransport()
{
    if (m_port->isOpen())
        m_port->close();
}

QString SerialTransport::systemPath(const QString &portName)
{
    return portName.startsWith(QLatin1Char('/')) ? portName : QStringLiteral("/dev/") + portName;
}

std::function<std::unique_ptr<Transport>(int)> SerialTransport::factory(SerialSettings settings)
{
    return [settings](int baud) {
        SerialSettings s = settings;
        s.baud = baud;
        return std::make_unique<SerialTransport>(s);
    };
}

QString SerialTransport::description() const
{
    return QStringLiteral("%1 @ %2").arg(m_path).arg(m_settings.baud);
}

bool SerialTransport::open()
{
    if (m_state == State::Open)
        return true;
    m_errorReported = false;
    const bool ok = openPort();
    if (!ok && m_state == State::Disconnected)
        setState(State::Closed);
    return ok;
}

bool SerialTransport::openPort()
{
    const auto fail = [&](const TransportError &e) {
        report(e);
        return false;
    };
    if (m_settings.baud <= 0)
        return fail(portError(TransportError::Kind::BadSettings, m_path, m_settings.baud));
    if (!QFileInfo::exists(m_path))
        return fail(portError(TransportError::Kind::NoSuchPort, m_path, 0, availablePortsText()));

    m_port->setPortName(m_path);
    m_port->setBaudRate(m_settings.baud);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    m_opening = true;
    const bool ok = m_port->open(isReadOnly() ? QIODevice::ReadOnly : QIODevice::ReadWrite);
    if (ok && isReadOnly())
        holdControlLinesInactive(); // inside m_opening: a refusal is no port error
    m_opening = false;
    if (!ok) {
        const TransportError e = openFailure(m_port->error(), m_port->errorString());
        m_port->clearError();
        return fail(e);
    }
    // QSerialPort applies the settings at open(); a driver may still refuse the baud later.
    if (m_port->baudRate() != m_settings.baud) {
        m_port->close();
        return fail(
            portError(TransportError::Kind::BadSettings, m_path, m_settings.baud,
                      QCoreApplication::translate("lk::transport::SerialTransport", "driver set %1")
                          .arg(m_port->baudRate())));
    }
    m_port->clear();
    enableLowLatency();
    m_errorReported = false;
    setState(State::Open);
    return true;
}

TransportError SerialTransport::openFailure(QSerialPort::SerialPortError error,
                                            const QString &detail) const
{
    using Kind = TransportError::Kind;
    if (error != QSerialPort::DeviceNotFoundError && error != QSerialPort::PermissionError) {
        // A regular file or /dev/null fails like a driver refusing the baud (ENOTTY): say
        // what it really is rather than suggest another baud.
        const QString what = nonTerminalKind(m_path);
        if (!what.isEmpty())
            return portError(Kind::NotSerialDevice, m_path, 0, what);
    }
    switch (error) {
    case QSerialPort::DeviceNotFoundError:
        return portError(Kind::NoSuchPort, m_path, 0, availablePortsText());
    case QSerialPort::PermissionError:
        // Qt reports both EACCES and "held by someone else" (EBUSY, TIOCEXCL, a lock file) as
        // PermissionError; if we may read and write the node, someone else holds it.
        if (::access(m_path.toLocal8Bit().constData(), R_OK | W_OK) == 0)
            return portError(Kind::PortBusy, m_path);
        return portError(Kind::PermissionDenied, m_path);
    case QSerialPort::UnsupportedOperationError:
        return portError(Kind::BadSettings, m_path, m_settings.baud, detail);
    default:
        return portError(Kind::IoError, m_path, 0, detail);
    }
}

void SerialTransport::enableLowLatency()
{
    m_lowLatency = false;
    if (!m_settings.lowLatency)
        return;
#ifdef Q_OS_LINUX
    // Best effort: ptys and some USB drivers have no serial_struct; that is not an error.
    const int fd = static_cast<int>(m_port->handle());
    serial_struct ss{};
    if (fd < 0 || ::ioctl(fd, TIOCGSERIAL, &ss) != 0)
        return;
    if (!(ss.flags & ASYNC_LOW_LATENCY)) {
        ss.flags |= ASYNC_LOW_LATENCY;
        if (::ioctl(fd, TIOCSSERIAL, &ss) != 0)
            return;
    }
    m_lowLatency = true;
#endif
}

void SerialTransport::holdControlLinesInactive()
{
    // Opening a tty raises DTR and RTS; an adapter that switches its RS485 driver on RTS would
    // then talk over the other master. Clear both where the driver lets us; a pty or a driver
    // without modem lines refuses, which is noted but no reason to fail a port that never
    // writes anyway.
    const bool rts = m_port->setRequestToSend(false);
    const bool dtr = m_port->setDataTerminalReady(false);
    m_controlLinesInactive = rts && dtr;
    if (!m_controlLinesInactive) {
        qCWarning(lcSerial).noquote()
            << QStringLiteral("%1: listen-only, the driver did not clear %2 (%3)")
                   .arg(m_path,
                        rts ? QStringLiteral("DTR")
                            : (dtr ? QStringLiteral("RTS") : QStringLiteral("RTS and DTR")),
                        m_port->errorString());
        m_port->clearError();
    }
}

void SerialTransport::close()
{
    if (m_port->isOpen())
        m_port->close();
    m_lowLatency = false;
    m_controlLinesInactive = false;
    setState(State::Closed);
}

void SerialTransport::write(const QByteArray &bytes)
{
    if (m_state != State::Open || refuseWriteIfReadOnly(bytes))
        return;
#ifdef Q_OS_UNIX
    // A request is a few bytes and the port is idle between transactions, so the kernel takes
    // it whole. Written straight to the descriptor it costs one system call; through
    // QSerialPort's buffer it also switches the write notifier on and off, and under the GLib
    // event dispatcher each switch wakes the bus thread's loop once more (three polls, reads
    // and writes per transaction instead of one, measured with strace at 1 Mbaud). Anything
    // the kernel does not take at once goes the buffered way, after what it took.
    const int fd = static_cast<int>(m_port->handle());
    if (fd >= 0 && m_port->bytesToWrite() == 0) {
        ssize_t n;
        do {
            n = ::write(fd, bytes.constData(), static_cast<size_t>(bytes.size()));
        } while (n < 0 && errno == EINTR);
        if (n == bytes.size())
            return;
        if (n > 0) {
            writeBuffered(bytes.mid(n));
            return;
        }
        // Nothing taken (full, or an error such as an unplug): QSerialPort tries again and
        // reports a failure the way the rest of this class expects it (onPortError).
    }
#endif
    writeBuffered(bytes);
}

void SerialTransport::writeBuffered(const QByteArray &bytes)
{
    if (m_port->write(bytes) != bytes.size()) {
        lostPort(TransportError::Kind::IoError, m_port->errorString());
        return;
    }
    // QSerialPort only buffers here and writes when the event loop next reports the port
    // writable: flush() writes now, which saves a loop turn on every transaction.
    m_port->flush();
}

void SerialTransport::onReadyRead()
{
    const QByteArray bytes = m_port->readAll();
    if (!bytes.isEmpty())
        emit bytesReceived(bytes);
}

void SerialTransport::onPortError(QSerialPort::SerialPortError error)
{
    if (error == QSerialPort::NoError || m_opening || m_state != State::Open)
        return;
    if (error == QSerialPort::TimeoutError)
        return; // only blocking waits produce it; not a fault of the link
    // An unplugged adapter shows up as ResourceError (EIO/ENXIO), sometimes as a read or
    // write error; the device node vanishing tells them apart from a mere I/O hiccup.
    const bool gone = error == QSerialPort::ResourceError || !QFileInfo::exists(m_path);
    lostPort(gone ? TransportError::Kind::Unplugged : TransportError::Kind::IoError,
             m_port->errorString());
}

void SerialTransport::lostPort(TransportError::Kind kind, const QString &detail)
{
    const TransportError e =
        portError(kind, m_path, 0, kind == TransportError::Kind::Unplugged ? QString() : detail);
    m_port->clearError();
    if (m_port->isOpen())
        m_port->close();
    m_lowLatency = false;
    report(e);
    setState(State::Disconnected);
}

void SerialTransport::report(const TransportError &error)
{
    if (m_errorReported)
        return;
    m_errorReported = true;
    qCWarning(lcSerial) << error.message;
    emit errorOccurred(error);
}

void SerialTransport::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

} // namespace lk::transport
