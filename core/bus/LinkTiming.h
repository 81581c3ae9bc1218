#pragma once

#include <protocol/Command.h>
#include <protocol/Series.h>

#include <QtCore/QVector>

#include <array>

namespace lk::bus {

/// The time a transaction takes on one link, as a value the engine can carry: the wire time
/// of request and reply, the drive's reply time, and the bus limit that follows from them.
/// RS485 is BusTiming's formula (8N1 bytes and a 0.5 ms turnaround); CAN counts the bits of
/// a classic 11-bit data frame of 8 bytes with worst-case bit stuffing, and the 0.25 ms a
/// V2.36 drive takes to answer (docs/CAN.md section 5).
class LinkTiming {
public:
    static constexpr double kCanReplyTimeS = 0.00025;
    static constexpr int kCanDefaultBitRate = 1000000;
    /// The bit rates LK drives take on CAN, fastest first (the old generation: 1 Mbit/s only).
    static const std::array<int, 5> &canBitRates();
    static bool isCanBitRate(int bitRate);

    /// Bits of a classic base-format data frame with `dataBytes` bytes, interframe space
    /// included: 47 + 8 n.
    static int canFrameBits(int dataBytes);
    /// The same with the most stuff bits the frame can carry: one per four bits of SOF..CRC.
    static int canFrameBitsStuffed(int dataBytes);

    static LinkTiming rs485(int baud);
    static LinkTiming can(int bitRate);
    /// The timing of `link` at `bitRate` (baud on RS485).
    static LinkTiming of(protocol::Link link, int bitRate);

    protocol::Link link() const { return m_link; }
    int bitRate() const { return m_bitRate; } ///< baud on RS485
    /// The time a drive takes to start its reply: 0.5 ms on RS485, 0.25 ms on CAN.
    double turnaroundS() const;

    /// One frame on the wire: `rs485Bytes` at 8N1 on RS485; on CAN every frame has 8 data
    /// bytes, whatever `rs485Bytes` says.
    double frameWireS(int rs485Bytes) const;
    double requestWireS(protocol::Command command) const;
    double replyWireS(protocol::Command command) const;    ///< the usual reply
    double maxReplyWireS(protocol::Command command) const; ///< the longest accepted reply
    /// Request and reply on the wire, no turnaround.
    double wireTimeS(protocol::Command command) const;
    double transactionTimeS(protocol::Command command) const;
    double transactionTimeS(protocol::Command command, double turnaroundS) const;
    /// Most transactions per second the link carries for a mix polled in equal shares.
    double transactionsPerSecond(const QVector<protocol::Command> &mix) const;
    double transactionsPerSecond(const QVector<protocol::Command> &mix, double turnaroundS) const;
    /// Wire time of the request and the longest accepted reply + turnaround + margin.
    double replyTimeoutS(protocol::Command command, double marginS) const;

private:
    LinkTiming(protocol::Link link, int bitRate) : m_link(link), m_bitRate(bitRate) {}
    double frameS(int rs485Bytes) const;

    protocol::Link m_link = protocol::Link::Rs485;
    int m_bitRate = 0;
};

} // namespace lk::bus
