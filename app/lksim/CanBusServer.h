#pragma once

#include <sim/SimBus.h>
#include <sim/SimCanFront.h>
#include <transport/CanTransport.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <atomic>
#include <memory>

namespace lk::app {

/// lksim --can: the simulated drives on a CAN interface through Qt SerialBus (virtualcan for
/// tests, socketcan for a vcan0 that can-utils watch). Requests arrive as CanRecords from
/// CanTransport; sim::SimCanFront answers with each drive's CAN generation (old on 0x140+ID,
/// V2.36 on 0x180+ID unless --can-reply-base says otherwise), after the drive's reply delay
/// and, with wire-time emulation, the CAN frames' wire time at the bit rate. The bus's faults
/// apply: dropped and late replies; a corrupt reply becomes what CAN makes of one, an error
/// frame on the bus and no reply (the controllers' CRC throws it away).
class CanBusServer : public QObject {
    Q_OBJECT
public:
    struct Options {
        transport::CanSettings can;
        bool emulateWireTime = false;
        bool verbose = false;
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
    void sendLater(const QByteArray &record, double delayS);

    sim::SimBus &m_bus;
    Options m_options;
    sim::SimCanFront m_front;
    std::unique_ptr<transport::CanTransport> m_transport;
    QElapsedTimer m_clock;
    qint64 m_wireFreeNs = 0; ///< when the emulated bus is next idle
    qint64 m_errorFrames = 0;
};

} // namespace lk::app
