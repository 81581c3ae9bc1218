#include "CanBusServer.h"

#include <protocol/CanFrameTime.h>
#include <protocol/CanRecord.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lk::app {

namespace {
constexpr int kStopPollMs = 50;
constexpr qint64 kGroupNs = 1000000; ///< replies closer than this are written together
/// CAN_ERR_PROT | CAN_ERR_CRC-style bus error: what a receiver reports for a frame whose CRC
/// failed (linux/can/error.h: CAN_ERR_PROT 0x08; data[3] location, CRC sequence 0x08).
constexpr quint32 kErrorClassProtocol = 0x00000008;
} // namespace

CanBusServer::CanBusServer(sim::SimBus &bus, const Options &options, QObject *parent)
    : QObject(parent), m_bus(bus), m_options(options), m_front(bus),
      m_controllerLog(options.controllerLog)
{
    m_clock.start();
    m_controllerTimer.setSingleShot(true);
    m_controllerTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_controllerTimer, &QTimer::timeout, this, &CanBusServer::tickController);
    connect(&m_wake, &transport::PreciseWake::woke, this, &CanBusServer::sendDue);
    m_coarseWake.setSingleShot(true);
    m_coarseWake.setTimerType(Qt::PreciseTimer);
    connect(&m_coarseWake, &QTimer::timeout, this, &CanBusServer::sendDue);
}

CanBusServer::~CanBusServer() = default;

bool CanBusServer::open()
{
    if (m_options.controller && !m_controllerLog.open())
        return false;
    transport::CanSettings s = m_options.can;
    s.setBitRate = m_options.can.plugin != QLatin1String("virtualcan");
    m_transport = std::make_unique<transport::CanTransport>(s);
    connect(m_transport.get(), &transport::Transport::bytesReceived, this,
            &CanBusServer::onRecords);
    connect(m_transport.get(), &transport::Transport::errorOccurred, this,
            [](const transport::TransportError &e) {
                std::fprintf(stderr, "lksim: %s\n", qPrintable(e.message));
            });
    return m_transport->open();
}

int CanBusServer::run(const std::atomic<bool> &stop)
{
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&stop] {
        if (stop.load())
            QCoreApplication::quit();
    });
    poll.start(kStopPollMs);
    if (m_options.controller) {
        m_controller.emplace(*m_options.controller, m_bus, m_front, m_options.can.bitRate,
                             nowSeconds());
        m_controllerTimer.start(0);
    }
    QCoreApplication::exec();
    if (m_transport)
        m_transport->close();
    return 0;
}

double CanBusServer::nowSeconds() const
{
    return static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
}

void CanBusServer::tickController()
{
    const double now = nowSeconds();
    for (const sim::CanWireFrame &f : m_controller->advanceTo(now)) {
        m_transport->write(f.record);
        if (m_options.verbose)
            std::fprintf(stderr, "lksim: controller %s\n",
                         qPrintable(protocol::CanRecord::decode(f.record)->candumpText()));
    }
    m_controllerLog.record(m_controller->takeFinished());
    // Frames go out in order, at most a millisecond late (the timer's grain): a listener hears
    // the conversation as it was, a little later.
    const double wait = std::clamp(m_controller->nextEventS() - now, 0.0, kStopPollMs * 1e-3);
    m_controllerTimer.start(static_cast<int>(std::ceil(wait * 1e3)));
}

void CanBusServer::onRecords(const QByteArray &records)
{
    const qint64 now = m_clock.nsecsElapsed();
    const double frameS =
        m_options.emulateWireTime ? protocol::can::frameSeconds(m_options.can.bitRate) : 0.0;
    const qint64 frameNs = std::llround(frameS * 1e9);
    const QList<sim::SimReply> replies = m_front.receive(records, static_cast<double>(now) * 1e-9);
    // The request was on the wire already (it reached us); each reply follows its drive's
    // turnaround and never overlaps the one before it.
    m_wireFreeNs = std::max(m_wireFreeNs, now);
    // Replies due within a millisecond of each other (a multi-motor frame's) go out together
    // at the last one's time: Qt's virtualcan (6.4) was seen to hold back the second of two
    // frames one client wrote 0.1 ms apart until the next frame came (drive 2's reply to a
    // 0x280 frame went missing), and our timeouts allow for the group's wire time anyway.
    QByteArray group;
    qint64 groupDueNs = 0;
    const auto sendGroup = [&] {
        if (!group.isEmpty())
            sendAt(group, groupDueNs);
        group.clear();
    };
    for (const sim::SimReply &r : replies) {
        QByteArray bytes = r.bytes;
        double extra = 0;
        if (!m_bus.faults().apply(bytes, extra))
            continue; // dropped: the drive acted, its reply was lost
        if (bytes != r.bytes) {
            // Corrupted on the wire: the CRC fails, every controller sends an error frame,
            // and the frame never reaches anyone's software.
            protocol::CanRecord err;
            err.canId = kErrorClassProtocol;
            err.flags = protocol::CanRecord::Error;
            err.data = QByteArray(8, '\0');
            ++m_errorFrames;
            sendAt(err.encode(), now);
            continue;
        }
        const qint64 start =
            std::max(now + std::llround((r.delaySeconds + extra) * 1e9), m_wireFreeNs);
        m_wireFreeNs = start + frameNs;
        if (!group.isEmpty() && m_wireFreeNs - groupDueNs >= kGroupNs)
            sendGroup();
        group += bytes;
        groupDueNs = m_wireFreeNs;
        if (m_options.verbose)
            std::fprintf(stderr, "lksim: reply %s\n",
                         qPrintable(protocol::CanRecord::decode(bytes)->candumpText()));
    }
    sendGroup();
}

void CanBusServer::sendAt(const QByteArray &record, qint64 due)
{
    // After every frame due no later: the wire's order, and an error frame at once.
    const auto at = std::upper_bound(m_outgoing.begin(), m_outgoing.end(), due,
                                     [](qint64 d, const Outgoing &o) { return d < o.dueNs; });
    m_outgoing.insert(at, Outgoing{due, record});
    sendDue();
}

void CanBusServer::sendDue()
{
    const qint64 now = m_clock.nsecsElapsed();
    while (!m_outgoing.empty() && m_outgoing.front().dueNs <= now) {
        const QByteArray record = m_outgoing.front().record;
        m_outgoing.pop_front();
        if (m_transport)
            m_transport->write(record);
    }
    if (m_outgoing.empty())
        return;
    const qint64 wait = m_outgoing.front().dueNs - now;
    if (m_wake.isValid())
        m_wake.wakeIn(wait);
    else
        m_coarseWake.start(static_cast<int>((wait + 999999) / 1000000));
}

QString CanBusServer::summary() const
{
    const sim::SimCanCounters &c = m_front.counters();
    const QString controller = m_controller
                                   ? QStringLiteral("lksim: controller: %1, %2 error frames\n")
                                         .arg(m_controllerLog.outcomesText())
                                         .arg(m_controller->errorFrames())
                                   : QString();
    return controller +
           QStringLiteral("lksim: %1 CAN requests, %2 replies, %3 unanswered, %4 faults, %5 "
                          "error frames sent, %6 frames heard that were no request (not answered)")
               .arg(c.requests)
               .arg(c.replies)
               .arg(c.unanswered)
               .arg(c.faults)
               .arg(m_errorFrames)
               .arg(c.notRequests);
}

} // namespace lk::app
