#pragma once

#include <protocol/Series.h>

#include <QtCore/QList>
#include <QtCore/QString>

namespace lk::ui {

/// What the connection bar asks to open: a serial port at a baud, a CAN interface through a
/// Qt SerialBus plugin at a bit rate, or the built-in simulator (on RS485, or on CAN with old
/// and V2.36 drives at a bit rate), either as the bus master or listening only (the tool then
/// transmits nothing, ever).
struct ConnectionChoice {
    enum class Kind { Serial, Simulator, Can };
    static constexpr int kDefaultBitRate = 1000000; ///< LK drives leave the factory at 1 Mbit/s
    Kind kind = Kind::Simulator;
    QString port; ///< serial device name or path ("ttyUSB0", "/dev/ttyUSB0"); Serial only
    int baud = 115200;
    QString canPlugin = QStringLiteral("socketcan"); ///< a key of QCanBus::plugins(); Can only
    QString canInterface = QStringLiteral("can0");   ///< "can0", "vcan0"; Can only
    int bitRate = kDefaultBitRate;                   ///< the drives' CAN bit rate; Can only
    bool autoReconnect = true;
    /// Watch a bus another controller runs: the link opens listen-only (bus::LinkMode).
    bool listenOnly = false;
    /// Simulator only: its drives sit on CAN at `bitRate` (CAN frames and their wire time; a
    /// V2.3 drive is an old CAN drive, a V2.35 one a V2.36 drive), not on RS485.
    bool simulatedCan = false;

    bool isSimulator() const { return kind == Kind::Simulator; }
    /// A real CAN interface (not the simulated CAN bus: see link()).
    bool isCan() const { return kind == Kind::Can; }
    /// The link the drives are on: CAN for a CAN interface and for the simulator on CAN.
    protocol::Link link() const
    {
        return isCan() || (isSimulator() && simulatedCan) ? protocol::Link::Can
                                                          : protocol::Link::Rs485;
    }
    /// The rate the link opens at: the bit rate on CAN, the baud on RS485.
    int rate() const { return link() == protocol::Link::Can ? bitRate : baud; }
    /// The CAN bit rates LK drives offer (V2.36: 1 M, 500 k, 250 k, 125 k, 100 k), fastest first.
    static QList<int> canBitRates() { return {1000000, 500000, 250000, 125000, 100000}; }
    static bool isCanBitRate(int bitRate) { return canBitRates().contains(bitRate); }
    bool operator==(const ConnectionChoice &o) const
    {
        return kind == o.kind && port == o.port && baud == o.baud && canPlugin == o.canPlugin &&
               canInterface == o.canInterface && bitRate == o.bitRate &&
               autoReconnect == o.autoReconnect && listenOnly == o.listenOnly &&
               simulatedCan == o.simulatedCan;
    }
    bool operator!=(const ConnectionChoice &o) const { return !(*this == o); }
};

} // namespace lk::ui
