#pragma once

#include "BusOptions.h"

#include <bus/BusSession.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/Series.h>
#include <protocol/Values.h>

#include <QtCore/QString>
#include <QtCore/QVector>

#include <functional>
#include <optional>

namespace lk::lkctl {

class Console;

/// A BusSession driven step by step for one lkctl command: each call runs the event loop
/// until its answer arrives (the engine completes every request exactly once, with a
/// timeout derived from the baud). Problems are printed as "lkctl CMD: ..." lines.
class LiveBus {
public:
    LiveBus(Console &console, QString command);
    ~LiveBus(); ///< closes the session

    /// Open the bus; on failure prints the transport's own message (with its fix) and
    /// returns false. A port another program holds is followed by which processes hold it
    /// (where the system tells), and `off`/`stop` say that no drive was stopped.
    bool open(const BusOptions &options);
    /// "/dev/ttyUSB0 is held open by process 4242 (lkstudio)", or that none is visible.
    static QString holdersText(const QString &device);
    /// The bus tunables for `options`: on CAN a fresh link's margin without a USB-serial
    /// chip's latency timer.
    static bus::BusConfig canConfig(const BusOptions &options);

    /// Send one request (already checked by MotionGuard if it moves a motor) and wait.
    /// `retries` as BusSession::send (0: sent exactly once, whatever it is).
    bus::RequestResult request(const protocol::Request &request,
                               bus::Priority priority = bus::Priority::Operator, int retries = -1);
    /// Send a request without data (reads, off/stop/run) to `id` and wait.
    bus::RequestResult request(protocol::Command command, int id,
                               bus::Priority priority = bus::Priority::Operator, int retries = -1);

    /// read_model from `id`; on success the session decodes its replies by the series the
    /// model names. nullopt after printing why (no reply, ...). On CAN, which has no model
    /// read: read_state1 shows the drive is there, and the generation and series are the
    /// user's (--drives) or, for the generation, what the reply told; `model` is empty but
    /// for its generation.
    struct Identity {
        protocol::ModelInfo model;
        std::optional<protocol::Series> series; ///< nullopt: the model names no series
        protocol::Reply reply;           ///< the read_model reply itself (`read model` prints it)
        std::optional<double> gearRatio; ///< CAN: the user's (--drives ID:SERIES@GEN/GEAR)
        /// False on CAN, which has no model read: `model` then holds only the generation.
        bool modelRead = true;
        /// Rotor turns per output turn: the user's (--drives), else the model name's ("-i36"),
        /// else 1. Every command that bounds or scales by the gearbox takes it from here.
        double gear() const;
    };
    std::optional<Identity> identify(int id);
    /// The link the bus opened on (RS485 until open()).
    protocol::Link link() const { return m_link; }

    bus::ScanSummary scan(const bus::ScanOptions &options);
    /// Motor off (or `halt` MotorStop) to `ids` plus every known ID (all of 1..32 when none),
    /// ahead of all else.
    struct StopOutcome {
        QVector<int> acknowledged, silent;
        QVector<int> unsent; ///< of the silent, those the halt never reached the wire for
    };
    StopOutcome emergencyStop(const QVector<int> &ids = {},
                              protocol::Command halt = protocol::Command::MotorOff);

    /// Print why a request failed, naming the ID and the command (with a hint on timeouts).
    void reportFailure(const bus::RequestResult &result);
    /// Run the event loop until `done` is true (a safety net ends it after `maxMs`).
    bool waitUntil(const std::function<bool()> &done, int maxMs = kMaxWaitMs);

    bus::BusSession &session() { return m_session; }
    Console &console() { return m_console; }
    void error(const QString &message); ///< "lkctl CMD: message" on standard error
    /// lkctl's one framing of a safety refusal (exit 4): "refused for safety[ for drive ID],
    /// nothing was sent: <clause>", the clause worded by text::VerdictText.
    void refused(const QString &clause, int id = 0);

    static constexpr int kMaxWaitMs = 120000;
    static constexpr int kTickMs = 100; ///< how late waitUntil may notice its deadline

private:
    std::optional<Identity> identifyOnCan(int id);
    /// Prints each new bad CAN bus condition (bus-off, error-passive, no-ACK) with its fix.
    void watchCanCondition();

    Console &m_console;
    QString m_command;
    bus::BusSession m_session;
    transport::CanBusCondition m_canCondition = transport::CanBusCondition::Good;
    protocol::Link m_link = protocol::Link::Rs485;
};

} // namespace lk::lkctl
