#include "BusTiming.h"

#include <protocol/Checksum.h>

#include <algorithm>

namespace lk::bus {

namespace {
int frameBytes(int len)
{
    return protocol::kHeaderSize + len + (len > 0 ? 1 : 0);
}
} // namespace

const std::array<int, 10> &BusTiming::standardBauds()
{
    // V2.3's nine and V2.35's 4 Mbaud (docs/V2.35.md section 1).
    static const std::array<int, 10> kBauds{9600,   19200,  38400,   57600,   115200,
                                            230400, 460800, 1000000, 2000000, 4000000};
    return kBauds;
}

bool BusTiming::isStandardBaud(int baud)
{
    const auto &b = standardBauds();
    return std::find(b.begin(), b.end(), baud) != b.end();
}

int BusTiming::requestBytes(protocol::Command command)
{
    return frameBytes(protocol::CommandTable::info(command).requestLength);
}

int BusTiming::replyBytes(protocol::Command command)
{
    return frameBytes(protocol::CommandTable::info(command).replyLength);
}

int BusTiming::maxReplyBytes(protocol::Command command)
{
    const protocol::CommandInfo &info = protocol::CommandTable::info(command);
    return frameBytes(std::max<int>(info.replyLength, info.altReplyLength));
}

double BusTiming::wireTimeS(int requestBytes, int replyBytes, int baud)
{
    if (baud <= 0)
        return 0;
    return static_cast<double>(requestBytes + replyBytes) * kBitsPerByte / baud;
}

double BusTiming::transactionTimeS(int requestBytes, int replyBytes, int baud, double turnaroundS)
{
    return wireTimeS(requestBytes, replyBytes, baud) + turnaroundS;
}

double BusTiming::transactionTimeS(protocol::Command command, int baud, double turnaroundS)
{
    return transactionTimeS(requestBytes(command), replyBytes(command), baud, turnaroundS);
}

double BusTiming::transactionsPerSecond(const QVector<protocol::Command> &mix, int baud,
                                        double turnaroundS)
{
    double cycle = 0;
    for (protocol::Command c : mix)
        cycle += transactionTimeS(c, baud, turnaroundS);
    return cycle > 0 ? mix.size() / cycle : 0;
}

double BusTiming::replyTimeoutS(protocol::Command command, int baud, double marginS)
{
    return transactionTimeS(requestBytes(command), maxReplyBytes(command), baud) + marginS;
}

} // namespace lk::bus
