#include "../support/FdAccessMode.h"

#include <transport/PortErrorText.h>
#include <transport/SerialTransport.h>

#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

using namespace lk::transport;
using Kind = TransportError::Kind;

Q_DECLARE_METATYPE(lk::transport::TransportError::Kind)

namespace {
/// A pseudo-terminal pair: the slave is a real serial device for QSerialPort.
struct Pty {
    int master = -1;
    QString slave;
    Pty()
    {
        int s = -1;
        char name[256] = {};
        if (::openpty(&master, &s, name, nullptr, nullptr) != 0)
            return;
        ::close(s); // QSerialPort opens it by name
        // Raw mode on the master side so that bytes pass unchanged.
        termios t{};
        ::tcgetattr(master, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(master, TCSANOW, &t);
        ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
        slave = QString::fromLocal8Bit(name);
    }
    ~Pty() { closeMaster(); }
    void closeMaster()
    {
        if (master >= 0)
            ::close(master);
        master = -1;
    }
    bool ok() const { return master >= 0 && !slave.isEmpty(); }
    QByteArray readMaster() const
    {
        char buf[512];
        const auto n = ::read(master, buf, sizeof buf);
        return n > 0 ? QByteArray(buf, int(n)) : QByteArray();
    }
};

SerialSettings settingsFor(const QString &port)
{
    SerialSettings s;
    s.portName = port;
    s.baud = 115200;
    return s;
}
} // namespace

/// SerialTransport over pseudo-terminals, and the wording of port errors.
class tst_SerialTransport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<TransportError>(); }
    void errorText_data();
    void errorText();
    void systemPath();
    void missingPort();
    void badBaud();
    void notASerialDevice_data();
    void notASerialDevice();
    void roundTripOverPty();
    void readOnlyOverPty();
    void busyPort();
    void permissionDenied();
    void unplugIsDisconnectedOnce();
    void reopensWhenDeviceReturns();
};

void tst_SerialTransport::errorText_data()
{
    QTest::addColumn<Kind>("kind");
    QTest::addColumn<QStringList>("mustContain");
    QTest::newRow("no such port") << Kind::NoSuchPort
                                  << QStringList{"No serial port /dev/ttyUSB0.", "plugged in"};
    QTest::newRow("permission") << Kind::PermissionDenied
                                << QStringList{"/dev/ttyUSB0", "dialout", "uucp", "log out"};
    QTest::newRow("busy") << Kind::PortBusy << QStringList{"/dev/ttyUSB0", "another program"};
    QTest::newRow("unplugged") << Kind::Unplugged << QStringList{"/dev/ttyUSB0", "unplugged"};
    QTest::newRow("bad settings") << Kind::BadSettings << QStringList{"/dev/ttyUSB0", "2000000"};
    QTest::newRow("io") << Kind::IoError << QStringList{"/dev/ttyUSB0"};
    QTest::newRow("not serial") << Kind::NotSerialDevice
                                << QStringList{"/dev/ttyUSB0 is not a serial device", "by-id"};
}

void tst_SerialTransport::errorText()
{
    QFETCH(Kind, kind);
    QFETCH(QStringList, mustContain);
    const TransportError e = portError(kind, QStringLiteral("/dev/ttyUSB0"), 2000000);
    QCOMPARE(e.kind, kind);
    for (const QString &s : mustContain)
        QVERIFY2(e.message.contains(s), qPrintable(e.message));
    const TransportError d = portError(kind, QStringLiteral("/dev/ttyUSB0"), 0, "EIO");
    QVERIFY(d.message.endsWith(QStringLiteral("(EIO)")));
    QVERIFY(portError(Kind::None, QStringLiteral("x")).message.isEmpty());
}

void tst_SerialTransport::systemPath()
{
    QCOMPARE(SerialTransport::systemPath("ttyUSB0"), QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(SerialTransport::systemPath("/dev/serial/by-id/x"),
             QStringLiteral("/dev/serial/by-id/x"));
}

void tst_SerialTransport::missingPort()
{
    SerialTransport t(settingsFor(QStringLiteral("/dev/ttyLKdoesNotExist7")));
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(!t.open());
    QCOMPARE(t.state(), Transport::State::Closed);
    QCOMPARE(errors.size(), 1);
    const auto e = errors.at(0).at(0).value<TransportError>();
    QCOMPARE(e.kind, Kind::NoSuchPort);
    QVERIFY(e.message.contains(QStringLiteral("/dev/ttyLKdoesNotExist7")));
}

void tst_SerialTransport::badBaud()
{
    Pty pty;
    QVERIFY(pty.ok());
    SerialSettings s = settingsFor(pty.slave);
    s.baud = 0;
    SerialTransport t(s);
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(!t.open());
    QCOMPARE(errors.at(0).at(0).value<TransportError>().kind, Kind::BadSettings);
}

void tst_SerialTransport::notASerialDevice_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("what");
    static QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("capture.txt"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("3E 80 01 00 BF\n");
    f.close();
    QTest::newRow("regular file") << file << "a regular file";
    QTest::newRow("directory") << dir.path() << "a directory";
    QTest::newRow("/dev/null") << "/dev/null"
                               << "a device that is not a terminal";
}

/// A regular file, a directory or /dev/null as the port is named for what it is, not
/// blamed on the baud (a pty, as lksim serves, is a serial device: roundTripOverPty).
void tst_SerialTransport::notASerialDevice()
{
    QFETCH(QString, path);
    QFETCH(QString, what);
    SerialTransport t(settingsFor(path));
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(!t.open());
    QCOMPARE(t.state(), Transport::State::Closed);
    QCOMPARE(errors.size(), 1);
    const auto e = errors.at(0).at(0).value<TransportError>();
    QVERIFY2(e.kind == Kind::NotSerialDevice, qPrintable(e.message));
    QVERIFY2(e.message.startsWith(path + QStringLiteral(" is not a serial device")),
             qPrintable(e.message));
    QVERIFY2(e.message.endsWith(QStringLiteral("(%1)").arg(what)), qPrintable(e.message));
    QVERIFY2(!e.message.contains(QStringLiteral("baud")), qPrintable(e.message));
}

void tst_SerialTransport::roundTripOverPty()
{
    Pty pty;
    QVERIFY(pty.ok());
    SerialTransport t(settingsFor(pty.slave));
    QSignalSpy state(&t, &Transport::stateChanged);
    QSignalSpy rx(&t, &Transport::bytesReceived);
    QVERIFY(t.open());
    QCOMPARE(t.state(), Transport::State::Open);
    QCOMPARE(state.size(), 1);
    QCOMPARE(t.description(), pty.slave + QStringLiteral(" @ 115200"));
    QVERIFY(!t.lowLatencyActive()); // a pty has no serial_struct: skipped silently

    const QByteArray out("\x3E\x9C\x01\x00\xDB", 5);
    t.write(out);
    QByteArray got;
    QTRY_VERIFY((got += pty.readMaster()).size() >= out.size());
    QCOMPARE(got, out);

    const QByteArray in("\x3E\x9C\x01\x07\xE2\x20\x00\x04\x5A\x00\xA0\x0F\x1D", 13);
    QCOMPARE(::write(pty.master, in.constData(), size_t(in.size())), ssize_t(in.size()));
    QByteArray received;
    QTRY_VERIFY([&] {
        received.clear();
        for (const auto &args : rx)
            received += args.at(0).toByteArray();
        return received.size() >= in.size();
    }());
    QCOMPARE(received, in);
    t.close();
    QCOMPARE(t.state(), Transport::State::Closed);
}

void tst_SerialTransport::readOnlyOverPty()
{
    // Listen-only: the port is opened for reading alone, RTS/DTR are cleared where the driver
    // allows (a pty does not: the open still succeeds), and write() drops and counts.
    Pty pty;
    QVERIFY(pty.ok());
    SerialTransport t(settingsFor(pty.slave));
    t.setReadOnly(true);
    QSignalSpy rx(&t, &Transport::bytesReceived);
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(t.open());
    QCOMPARE(t.state(), Transport::State::Open);
    QCOMPARE(lk::testsupport::accessModeOf(QCoreApplication::applicationPid(), pty.slave),
             O_RDONLY);
    QVERIFY(errors.isEmpty()); // a refused RTS/DTR is a warning, not a port error

    const QByteArray out("\x3E\x9C\x01\x00\xDB", 5);
    t.write(out);
    QCOMPARE(t.refusedWrites(), quint64(out.size()));

    const QByteArray in("\x3E\x9C\x01\x00\xDB", 5);
    QCOMPARE(::write(pty.master, in.constData(), size_t(in.size())), ssize_t(in.size()));
    QTRY_VERIFY(!rx.isEmpty());
    QCOMPARE(rx.at(0).at(0).toByteArray(), in);
    QCOMPARE(pty.readMaster(), QByteArray()); // the refused bytes never reached the line
    t.close();

    SerialTransport rw(settingsFor(pty.slave)); // the default stays read-write
    QVERIFY(rw.open());
    QCOMPARE(lk::testsupport::accessModeOf(QCoreApplication::applicationPid(), pty.slave), O_RDWR);
}

void tst_SerialTransport::busyPort()
{
    Pty pty;
    QVERIFY(pty.ok());
    SerialTransport first(settingsFor(pty.slave));
    QVERIFY(first.open());
    SerialTransport second(settingsFor(pty.slave));
    QSignalSpy errors(&second, &Transport::errorOccurred);
    QVERIFY(!second.open());
    QCOMPARE(errors.size(), 1);
    const auto e = errors.at(0).at(0).value<TransportError>();
    QVERIFY2(e.kind == Kind::PortBusy, qPrintable(e.message));
    QVERIFY(e.message.contains(pty.slave));
}

void tst_SerialTransport::permissionDenied()
{
    if (::geteuid() == 0)
        QSKIP("root may open any device: permission errors cannot be provoked");
    Pty pty;
    QVERIFY(pty.ok());
    QVERIFY(QFile::setPermissions(pty.slave, QFileDevice::Permissions{}));
    SerialTransport t(settingsFor(pty.slave));
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(!t.open());
    const auto e = errors.at(0).at(0).value<TransportError>();
    QVERIFY2(e.kind == Kind::PermissionDenied, qPrintable(e.message));
    QVERIFY(e.message.contains(QStringLiteral("dialout")));
}

void tst_SerialTransport::unplugIsDisconnectedOnce()
{
    Pty pty;
    QVERIFY(pty.ok());
    SerialTransport t(settingsFor(pty.slave));
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QSignalSpy state(&t, &Transport::stateChanged);
    QVERIFY(t.open());
    pty.closeMaster(); // the "adapter" goes away: reads on the slave fail with EIO
    QTRY_COMPARE_WITH_TIMEOUT(t.state(), Transport::State::Disconnected, 10000);
    QTest::qWait(200);
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.at(0).at(0).value<TransportError>().kind, Kind::Unplugged);
    QCOMPARE(state.last().at(0).value<Transport::State>(), Transport::State::Disconnected);
    t.write("x"); // dropped, no crash, no second error
    QCOMPARE(errors.size(), 1);
}

void tst_SerialTransport::reopensWhenDeviceReturns()
{
    // The transport does not reconnect by itself (BusController owns that, switchable live):
    // it stays Disconnected until asked, and open() then works on the returned device.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyLK"));
    auto first = std::make_unique<Pty>();
    QVERIFY(first->ok());
    QVERIFY(QFile::link(first->slave, link));
    SerialTransport t(settingsFor(link));
    QSignalSpy errors(&t, &Transport::errorOccurred);
    QVERIFY(t.open());

    first->closeMaster();
    QFile::remove(link); // the device node is gone
    QTRY_COMPARE_WITH_TIMEOUT(t.state(), Transport::State::Disconnected, 10000);
    QTest::qWait(500);
    QCOMPARE(t.state(), Transport::State::Disconnected);

    Pty second; // the adapter is plugged back in
    QVERIFY(second.ok());
    QVERIFY(QFile::link(second.slave, link));
    QTest::qWait(1000);
    QCOMPARE(t.state(), Transport::State::Disconnected); // no reconnect of its own
    QVERIFY(t.open());
    QCOMPARE(t.state(), Transport::State::Open);
    QCOMPARE(errors.size(), 1); // the unplug, once

    t.write(QByteArray("\x3E\x80\x01\x00\xBF", 5));
    QByteArray got;
    QTRY_VERIFY((got += second.readMaster()).size() >= 5);
}

QTEST_GUILESS_MAIN(tst_SerialTransport)
#include "tst_serialtransport.moc"
