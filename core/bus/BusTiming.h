#pragma once

#include <protocol/Command.h>

#include <QtCore/QVector>

#include <array>

namespace lk::bus {

/// The bus-limit formula of docs/ARCHITECTURE.md: a half-duplex 8N1 transaction costs
/// (request_bytes + reply_bytes) * 10 / baud + t_turnaround.
class BusTiming {
public:
    static constexpr int kBitsPerByte = 10;        ///< 8N1: start + 8 data + stop
    static constexpr double kTurnaroundS = 0.0005; ///< a drive replies within 0.5 ms
    static constexpr int kDefaultBaud = 115200;

    /// The ten bauds LK drives support (4 Mbaud from firmware 2.35 on), slowest first.
    static const std::array<int, 10> &standardBauds();
    static bool isStandardBaud(int baud);

    /// Frame sizes on the wire (header, data and data checksum) for a command.
    static int requestBytes(protocol::Command command);
    static int replyBytes(protocol::Command command);    ///< the usual reply LEN
    static int maxReplyBytes(protocol::Command command); ///< the longest accepted reply

    static double wireTimeS(int requestBytes, int replyBytes, int baud);
    static double transactionTimeS(int requestBytes, int replyBytes, int baud,
                                   double turnaroundS = kTurnaroundS);
    static double transactionTimeS(protocol::Command command, int baud,
                                   double turnaroundS = kTurnaroundS);
    /// Most transactions per second the bus carries for a mix polled in equal shares.
    static double transactionsPerSecond(const QVector<protocol::Command> &mix, int baud,
                                        double turnaroundS = kTurnaroundS);
    /// Wire time of the longest accepted reply + turnaround + margin.
    static double replyTimeoutS(protocol::Command command, int baud, double marginS);
};

} // namespace lk::bus
