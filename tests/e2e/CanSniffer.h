#pragma once

#include "CanLksim.h"
#include "E2eUtil.h"
#include "LksimProcess.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtSerialBus/QCanBus>
#include <QtSerialBus/QCanBusDevice>
#include <QtSerialBus/QCanBusFrame>
#include <QtTest/QTest>

#include <memory>

namespace lk::e2e {

/// One frame seen on the virtual bus: its 11-bit ID and its eight data bytes.
struct SniffedFrame {
    quint32 id = 0;
    QByteArray data;
    quint8 command() const { return data.isEmpty() ? 0 : quint8(data.at(0)); }
    /// candump notation, e.g. 141#9C00000000000000.
    QString text() const
    {
        return QStringLiteral("%1#%2")
            .arg(id, 3, 16, QLatin1Char('0'))
            .arg(QString::fromLatin1(data.toHex()))
            .toUpper();
    }
};

/// A third node on lksim's virtualcan bus that only listens: every frame lkctl sends and every
/// reply lksim gives, as the wire carried them, independent of both programs' own logs.
/// Connect it after lksim started (lksim then holds the virtualcan server of the port).
class CanSniffer {
public:
    bool open(const QString &url)
    {
        QString error;
        m_device.reset(
            QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), url, &error));
        if (!m_device || !m_device->connectDevice())
            return false;
        QObject::connect(m_device.get(), &QCanBusDevice::framesReceived, [this] { drain(); });
        return QTest::qWaitFor(
            [this] { return m_device->state() == QCanBusDevice::ConnectedState; }, 30000);
    }

    void close()
    {
        m_device.reset();
        m_frames.clear();
    }

    /// Everything seen so far.
    const QList<SniffedFrame> &frames()
    {
        drain();
        return m_frames;
    }
    void clear()
    {
        drain();
        m_frames.clear();
    }

    /// Frames on `id` whose B0 is `command` (the request and, old CAN, its reply).
    QList<SniffedFrame> on(quint32 id, quint8 command)
    {
        QList<SniffedFrame> out;
        for (const SniffedFrame &f : frames()) {
            if (f.id == id && f.command() == command)
                out.append(f);
        }
        return out;
    }
    int count(quint32 id, quint8 command) { return int(on(id, command).size()); }

    /// Waits (generously: the machine may be loaded) until `n` frames of `command` on `id`
    /// were seen.
    bool waitFor(quint32 id, quint8 command, int n = 1, int timeoutMs = 30000)
    {
        return QTest::qWaitFor([&] { return count(id, command) >= n; }, timeoutMs);
    }

    /// The last frame of `command` on `id` (a reply is seen after its request), or an empty one.
    SniffedFrame last(quint32 id, quint8 command)
    {
        const QList<SniffedFrame> f = on(id, command);
        return f.isEmpty() ? SniffedFrame{} : f.last();
    }

private:
    void drain()
    {
        if (!m_device)
            return;
        while (m_device->framesAvailable() > 0) {
            const QCanBusFrame f = m_device->readFrame();
            if (f.frameType() == QCanBusFrame::DataFrame)
                m_frames.append({f.frameId(), f.payload()});
        }
    }

    std::unique_ptr<QCanBusDevice> m_device;
    QList<SniffedFrame> m_frames;
};

/// Run `program` with `args`, this thread's event loop running meanwhile (a CanSniffer keeps
/// hearing the wire); generous timeout, the machine may be loaded.
inline CtlResult lkctlHeard(const QString &program, const QStringList &args)
{
    QProcess p;
    p.start(program, args);
    CtlResult r;
    if (!p.waitForStarted(60000))
        return r;
    p.closeWriteChannel();
    if (!QTest::qWaitFor([&p] { return p.state() == QProcess::NotRunning; }, 120000)) {
        p.kill();
        p.waitForFinished(5000);
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

#if defined(LKCTL_PATH) && defined(LKSIM_PATH)
/// What every CAN end-to-end test starts from: lksim --can on a virtualcan port of its own,
/// a CanSniffer on the same bus, and lkctl runs the sniffer hears.
class CanE2eBus {
public:
    /// Starts lksim with `motors` (with wire time); `marker` (e.g. "1:MG@can") is a drive of
    /// them whose single-turn read shows the sniffer hears the bus: the server forwards
    /// frames only once it read the sniffer's "connect:can0" line. Empty, or what failed.
    QString start(const QString &motors, const QString &marker)
    {
        if (const QString failed = m_sim.start(motors, {QStringLiteral("--wire-time")});
            !failed.isEmpty())
            return failed;
        if (!m_wire.open(can().mid(QStringLiteral("virtualcan:").size())))
            return QStringLiteral("the sniffer could not join %1").arg(can());
        const quint32 id = 0x140 + marker.section(QLatin1Char(':'), 0, 0).toUInt();
        const bool heard = QTest::qWaitFor(
            [&] {
                const CtlResult r =
                    run({QStringLiteral("read"), marker.section(':', 0, 0),
                         QStringLiteral("single-turn"), QStringLiteral("--drives"), marker});
                return r.exitCode == 0 && m_wire.waitFor(id, 0x94, 1, 2000);
            },
            60000);
        return heard ? QString() : QStringLiteral("the sniffer heard no frame on %1").arg(can());
    }
    void stop()
    {
        m_wire.close();
        m_sim.stop();
    }
    /// lkctl ARGS --can (this bus), the sniffer hearing the wire while it runs.
    CtlResult run(const QStringList &args)
    {
        return lkctlHeard(QStringLiteral(LKCTL_PATH), args + m_sim.can());
    }
    CanSniffer &wire() { return m_wire; }
    QString can() const { return m_sim.url(); }

private:
    CanLksim m_sim;
    CanSniffer m_wire;
};
#endif

/// Little-endian integers of a sniffed frame's data bytes (B0 = the command).
inline qint64 leBytes(const QByteArray &d, int from, int n, bool isSigned)
{
    quint64 v = 0;
    for (int i = n - 1; i >= 0; --i)
        v = (v << 8) | quint8(d.at(from + i));
    if (isSigned && n < 8 && (v & (quint64(1) << (8 * n - 1))))
        v |= ~quint64(0) << (8 * n);
    return qint64(v);
}

} // namespace lk::e2e
