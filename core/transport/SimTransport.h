#pragma once

#include "Transport.h"

#include <sim/SimBusSpec.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QString>

#include <QtCore/QList>

#include <deque>
#include <functional>
#include <memory>

class QTimer;

namespace lk::sim {
class SimBus;
class SimCanFront;
struct SimReply;
} // namespace lk::sim

namespace lk::transport {

class PreciseWake;

/// What a simulated link is made of: a plain value, the counterpart of SerialSettings.
struct SimSettings {
    sim::SimBusSpec spec; ///< the drives
    QString romDirectory; ///< where the drives keep their ROM between links (empty: memory only)
    QString faultSpec;    ///< faults in every reply (FaultInjector::configure syntax), checked
                          ///< by the caller; empty: none
    /// Can: the drives sit on CAN (sim::SimCanFront) and the link carries CanRecords; a drive
    /// of generation V2_3 is an old CAN drive, V2_35 a V2.36 one.
    protocol::Link link = protocol::Link::Rs485;
};

/// A Transport over an in-process simulated bus (sim::SimBus), for the embedded default
/// bus of lkstudio, for tests and for benchmarks.
///
/// write() feeds the bus at once (physics advanced to a QElapsedTimer clock); each reply
/// arrives through bytesReceived after the bus's reply delay (0.2 ms by default) plus, if
/// enabled, the 8N1 wire time of request and reply at the emulated baud. Replies are never
/// delivered inside write(). A FaultInjector disconnect turns the link Disconnected with an
/// Unplugged error; open() reconnects. Lives on the bus thread like every Transport.
class SimTransport : public Transport {
    Q_OBJECT
public:
    static constexpr int kDefaultBaud = 115200;

    explicit SimTransport(std::unique_ptr<sim::SimBus> bus, QObject *parent = nullptr);
    ~SimTransport() override;
    /// A transport factory for BusSession, beside SerialTransport::factory: a fresh simulated
    /// bus of `settings` per (re)open, at the session's `baud` and with the wire time of that
    /// baud. lkstudio's built-in bus and lkctl --sim both build their link with it, so that
    /// they report the same rates and timings as each other and as lksim --wire-time.
    static std::function<std::unique_ptr<Transport>(int baud)> factory(SimSettings settings);

    bool open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    State state() const override { return m_state; }
    int baud() const override { return m_baud; }
    QString description() const override;
    protocol::Link link() const override { return m_link; }

    /// Put the drives on CAN (before open()): records in and out through sim::SimCanFront,
    /// and the wire time of CAN frames at baud() (the bit rate) when emulated.
    void setLink(protocol::Link link);
    /// The CAN front end (null on RS485), e.g. to choose the reply ID base.
    sim::SimCanFront *canFront() { return m_canFront.get(); }

    /// The baud that baud() reports and wire-time emulation uses.
    void setBaud(int baud);
    /// Delay replies by the time request and reply bytes take on the wire at baud().
    void setWireTimeEmulation(bool on) { m_wireTime = on; }
    /// Drive turnaround (seconds) before each reply; forwards to the bus.
    void setReplyDelay(double seconds);
    double replyDelay() const;

    /// The simulated bus: drives, faults, counters. Use it only from this object's thread.
    sim::SimBus &bus() { return *m_bus; }
    int pendingReplies() const { return static_cast<int>(m_pending.size()); }
    /// How often the due replies were looked for: a reply a wait should cost one or two,
    /// not the thousands of event-loop turns of polling.
    int wakeups() const { return m_wakeups; }

private:
    struct Pending {
        QByteArray bytes;
        qint64 dueNs = 0;
    };
    qint64 wireNs(qsizetype bytes) const;
    QList<sim::SimReply> receive(const QByteArray &bytes, double nowSeconds);
    void schedule();
    void postCheck();
    void deliverDue();
    void housekeeping();
    void goDisconnected();
    void setState(State state);

    std::unique_ptr<sim::SimBus> m_bus;
    std::unique_ptr<sim::SimCanFront> m_canFront;
    protocol::Link m_link = protocol::Link::Rs485;
    QElapsedTimer m_clock;
    PreciseWake *m_wake = nullptr;    ///< the next reply's due time, to the microsecond
    QTimer *m_timer = nullptr;        ///< without a timerfd: waits of 1 ms or more
    QTimer *m_housekeeping = nullptr; ///< disconnect flag and idle physics, 10 Hz while open
    std::deque<Pending> m_pending;    ///< in due order
    qint64 m_wireFreeNs = 0;          ///< when the emulated wire is next idle
    bool m_checkPosted = false;
    int m_wakeups = 0;
    State m_state = State::Closed;
    int m_baud = kDefaultBaud;
    bool m_wireTime = false;
};

} // namespace lk::transport
