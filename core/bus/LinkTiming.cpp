#include "LinkTiming.h"

#include "BusTiming.h"

#include <protocol/CanFrameTime.h>

#include <algorithm>

namespace lk::bus {

const std::array<int, 5> &LinkTiming::canBitRates()
{
    static const std::array<int, 5> kRates{1000000, 500000, 250000, 125000, 100000};
    return kRates;
}

bool LinkTiming::isCanBitRate(int bitRate)
{
    const auto &r = canBitRates();
    return std::find(r.begin(), r.end(), bitRate) != r.end();
}

int LinkTiming::canFrameBits(int dataBytes)
{
    return protocol::can::frameBits(dataBytes);
}

int LinkTiming::canFrameBitsStuffed(int dataBytes)
{
    return protocol::can::frameBitsStuffed(dataBytes);
}

LinkTiming LinkTiming::rs485(int baud)
{
    return LinkTiming(protocol::Link::Rs485, baud);
}

LinkTiming LinkTiming::can(int bitRate)
{
    return LinkTiming(protocol::Link::Can, bitRate);
}

LinkTiming LinkTiming::of(protocol::Link link, int bitRate)
{
    return LinkTiming(link, bitRate);
}

double LinkTiming::turnaroundS() const
{
    return m_link == protocol::Link::Can ? kCanReplyTimeS : BusTiming::kTurnaroundS;
}

double LinkTiming::frameS(int rs485Bytes) const
{
    if (m_bitRate <= 0)
        return 0;
    // Every LK frame on CAN has 8 data bytes, whatever the command.
    if (m_link == protocol::Link::Can)
        return protocol::can::frameSeconds(m_bitRate);
    return BusTiming::wireTimeS(rs485Bytes, 0, m_bitRate);
}

double LinkTiming::frameWireS(int rs485Bytes) const
{
    return frameS(rs485Bytes);
}

double LinkTiming::requestWireS(protocol::Command command) const
{
    return frameS(BusTiming::requestBytes(command));
}

double LinkTiming::replyWireS(protocol::Command command) const
{
    return frameS(BusTiming::replyBytes(command));
}

double LinkTiming::maxReplyWireS(protocol::Command command) const
{
    return frameS(BusTiming::maxReplyBytes(command));
}

double LinkTiming::wireTimeS(protocol::Command command) const
{
    return requestWireS(command) + replyWireS(command);
}

double LinkTiming::transactionTimeS(protocol::Command command) const
{
    return transactionTimeS(command, turnaroundS());
}

double LinkTiming::transactionTimeS(protocol::Command command, double turnaroundS) const
{
    return wireTimeS(command) + turnaroundS;
}

double LinkTiming::transactionsPerSecond(const QVector<protocol::Command> &mix) const
{
    return transactionsPerSecond(mix, turnaroundS());
}

double LinkTiming::transactionsPerSecond(const QVector<protocol::Command> &mix,
                                         double turnaroundS) const
{
    double cycle = 0;
    for (protocol::Command c : mix)
        cycle += transactionTimeS(c, turnaroundS);
    return cycle > 0 ? mix.size() / cycle : 0;
}

double LinkTiming::replyTimeoutS(protocol::Command command, double marginS) const
{
    return requestWireS(command) + maxReplyWireS(command) + turnaroundS() + marginS;
}

} // namespace lk::bus
