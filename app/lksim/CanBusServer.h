#pragma once

#include "ControllerLogFile.h"

#include <sim/CanForeignController.h>
#include <sim/ControllerSpec.h>
#include <sim/SimBus.h>
#include <sim/SimCanFront.h>
#include <transport/CanTransport.h>
#include <transport/PreciseWake.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QTimer>

#include <atomic>
#include <deque>
#include <memory>
#include <optional>

namespace lk::app {

/// lksim --can: the simulated drives on a CAN interface through Qt SerialBus (virtualcan for
/// tests, socketcan for a vcan0 that can-utils watch). Requests arrive as CanRecords from
/// CanTransport; sim::SimCanFront answers with each drive's CAN generation (old on 0x140+ID,
/// V2.36 on 0x180+ID unless --can-reply-base says otherwise), after the drive's reply delay
/// and, with wire-time emulation, the CAN frames' wire time at the bit rate. The bus's faults
/// apply: dropped and late replies; a corrupt reply becomes what CAN makes of one, an error
/// frame on the bus and no reply (the controllers' CRC throws it away). Only requests are
/// answered (SimCanFront): another node's replies on the bus are ignored.
///
/// With a controller (--controller), a simulated foreign master (sim::CanForeignController)
/// asks the drives in this process and every frame of its conversation, requests, replies and
/// error frames, goes on the bus in order when it is due, so that a listener on the same bus
/// hears exactly that conversation; each finished request is a line of the controller log.
/// Frames of other hosts are still answered, as another master's (CAN arbitrates: they do not
/// collide with the controller's).
class CanBusServer : public QObject {
    Q_OBJECT
public:
    struct Options {
        transport::CanSettings can;
        bool emulateWireTime = false;
        bool verbose = false;
        std::optional<sim::ControllerSpec> controller;
        QString controllerLog; ///< with a controller: its ground-truth log (empty: none)
    };
    CanBusServer(sim::SimBus &bus, const Options &options, QObject *parent = nullptr);
    ~CanBusServer() override;

    /// Opens the interface; false after printing why.
    bool open();
    /// Serves until `stop` is raised; the exit status.
    int run(const std::atomic<bool> &stop);
    sim::SimCanFront &front() { return m_front; }
    QString summary() const;

private:
    void onRecords(const QByteArray &records);
    /// Puts `record` on the bus when m_clock reaches `dueNs`, to the microsecond, after the
    /// frames due no later.
    void sendAt(const QByteArray &record, qint64 dueNs);
    /// Writes every frame that is due and waits for the next.
    void sendDue();
    double nowSeconds() const;
    /// Runs the controller to now, puts its due frames on the bus and waits for the next.
    void tickController();

    sim::SimBus &m_bus;
    Options m_options;
    sim::SimCanFront m_front;
    std::unique_ptr<transport::CanTransport> m_transport;
    QElapsedTimer m_clock;
    qint64 m_wireFreeNs = 0; ///< when the emulated bus is next idle
    qint64 m_errorFrames = 0;
    std::optional<sim::CanForeignController> m_controller; ///< made when serving starts
    ControllerLogFile m_controllerLog;
    QTimer m_controllerTimer;
    struct Outgoing {
        qint64 dueNs = 0;
        QByteArray record;
    };
    std::deque<Outgoing> m_outgoing; ///< in due order
    transport::PreciseWake m_wake;   ///< a frame's wire time is a tenth of QTimer's grain
    QTimer m_coarseWake;             ///< without a timerfd: whole milliseconds, late
};

} // namespace lk::app
