#pragma once

#include "Transport.h"

#include <QtCore/QString>
#include <QtSerialPort/QSerialPort>

#include <functional>
#include <memory>

namespace lk::transport {

/// How to open a serial port: a plain value, as in Qt's serialport examples.
struct SerialSettings {
    QString portName;       ///< "/dev/ttyUSB0" or "ttyUSB0"
    int baud = 115200;      ///< any of the nine LK bauds (others are passed to the driver)
    bool lowLatency = true; ///< ask the Linux driver for ASYNC_LOW_LATENCY (FTDI: 16 -> 1 ms)
};

/// A Transport over QSerialPort: 8N1, no flow control. Construct it on the thread that uses
/// it (the bus thread). An unplug while open becomes state Disconnected plus one Unplugged
/// error per connect cycle. Reconnecting is the owner's job (BusController, which the user
/// can switch live): one reconnect mechanism, not two.
class SerialTransport : public Transport {
    Q_OBJECT
public:
    explicit SerialTransport(const SerialSettings &settings, QObject *parent = nullptr);
    ~SerialTransport() override;

    bool open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    State state() const override { return m_state; }
    int baud() const override { return m_settings.baud; }
    QString description() const override;

    const SerialSettings &settings() const { return m_settings; }
    /// The low_latency flag is set on the open port (false on ptys and non-Linux systems).
    bool lowLatencyActive() const { return m_lowLatency; }
    /// Read-only: RTS and DTR were cleared after the open (an RTS-switched RS485 adapter then
    /// never drives the bus). False where the driver refused (ptys, some adapters): the open
    /// still succeeds, a warning says so, and the port still never writes.
    bool controlLinesInactive() const { return m_controlLinesInactive; }

    /// "ttyUSB0" -> "/dev/ttyUSB0"; absolute paths unchanged.
    static QString systemPath(const QString &portName);
    /// A transport factory for BusSession: a new SerialTransport per (re)open at `baud`, the
    /// session's (open(), and each baud of a scan sweep): `settings.baud` is not used, so the
    /// baud is given in one place.
    static std::function<std::unique_ptr<Transport>(int baud)> factory(SerialSettings settings);

private:
    bool openPort();
    void onPortError(QSerialPort::SerialPortError error);
    void onReadyRead();
    void lostPort(TransportError::Kind kind, const QString &detail);
    /// Through QSerialPort's buffer, written out at once (flush()).
    void writeBuffered(const QByteArray &bytes);
    void setState(State state);
    void report(const TransportError &error);
    TransportError openFailure(QSerialPort::SerialPortError error, const QString &detail) const;
    void enableLowLatency();
    void holdControlLinesInactive();

    SerialSettings m_settings;
    QString m_path;
    QSerialPort *m_port;
    State m_state = State::Closed;
    bool m_opening = false;
    bool m_errorReported = false; ///< one error per connect cycle
    bool m_lowLatency = false;
    bool m_controlLinesInactive = false;
};

} // namespace lk::transport
