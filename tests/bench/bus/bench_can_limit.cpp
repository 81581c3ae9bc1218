// The CAN bus limit from LinkTiming, beside the RS485 figure, and what the CAN codec costs
// per transaction on this machine (request encoded into a record, the reply record parsed and
// decoded): the ceiling the poll ratio is measured against.
//
// Prints one JSON line: can_<rate>_frame_bits (stuffed worst case), can_<rate>_transaction_ms,
// can_<rate>_limit_per_s for 0x9C alone and can_<rate>_poll_mix_limit_per_s for 0x9C, 0x9A
// and 0x92 in equal shares, at 1 Mbit/s and 500 kbit/s; rs485_115200_limit_per_s; and
// codec_us_per_transaction (median of 5 runs of 200000).
//
//   cmake --build build --target run_bench_can_limit

#include "BenchUtil.h"

#include <bus/LinkTiming.h>
#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <protocol/LinkCodec.h>

#include <QtCore/QElapsedTimer>

#include <cstdio>

using namespace lk;
using bus::LinkTiming;
using protocol::Command;

namespace {

double codecMicroseconds(int transactions)
{
    const protocol::DecodeContext ctx{protocol::Series::MF, protocol::Generation::V2_35,
                                      protocol::Link::Can};
    const protocol::Request request{Command::ReadState2, 1, protocol::NoPayload{}};
    const QByteArray reply =
        protocol::CanRecord::of(
            protocol::can::CanData{0x181, QByteArray::fromHex("9C326400F4010020")})
            .encode();
    protocol::CanRecordParser parser;
    qint64 sink = 0;
    QElapsedTimer t;
    t.start();
    for (int i = 0; i < transactions; ++i) {
        sink += protocol::encodeRequest(request, ctx).bytes.size();
        parser.feed(reply, [&](const protocol::ParseEvent &e) {
            const auto r = protocol::decodeReply(e.frame, ctx);
            sink += std::get<protocol::State2>(r.reply->payload).encoder;
        });
    }
    const double us = t.nsecsElapsed() / 1e3 / transactions;
    if (sink == 42)
        std::puts(""); // keeps the loop from being optimised away
    return us;
}

} // namespace

int main()
{
    const QVector<Command> one{Command::ReadState2};
    const QVector<Command> mix{Command::ReadState2, Command::ReadState1, Command::ReadMultiTurn};
    bench::JsonLine json;
    for (int rate : {1000000, 500000}) {
        const LinkTiming t = LinkTiming::can(rate);
        const QString key = QStringLiteral("can_%1k_").arg(rate / 1000);
        json.addInt(key + QStringLiteral("frame_bits"),
                    LinkTiming::canFrameBitsStuffed(protocol::can::kDataSize));
        json.add(key + QStringLiteral("transaction_ms"),
                 1e3 * t.transactionTimeS(Command::ReadState2));
        json.add(key + QStringLiteral("limit_per_s"), t.transactionsPerSecond(one), 0);
        json.add(key + QStringLiteral("poll_mix_limit_per_s"), t.transactionsPerSecond(mix), 0);
    }
    json.add(QStringLiteral("rs485_115200_limit_per_s"),
             LinkTiming::rs485(115200).transactionsPerSecond(one), 0);
    std::vector<double> runs;
    for (int i = 0; i < 5; ++i)
        runs.push_back(codecMicroseconds(200000));
    json.add(QStringLiteral("codec_us_per_transaction"), bench::median(runs));
    json.print();
    return 0;
}
