// libFuzzer target: arbitrary bytes through StreamParser (in input-chosen chunk sizes), then
// every frame through decodeRequest and decodeReply. Aborts on any broken invariant.
#include "protocol/Checksum.h"
#include "protocol/Reply.h"
#include "protocol/Request.h"
#include "protocol/StreamParser.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace {
using namespace lk::protocol;

void require(bool ok)
{
    if (!ok)
        std::abort();
}

// StreamParser.h: between calls the parser holds at most one partial frame (under
// kMaxFrameSize bytes) and one run of garbage (under 4 KiB; a full 4 KiB run is reported).
constexpr qsizetype kMaxHeldGarbage = 4096;
constexpr qsizetype kMaxPendingBytes = (kMaxFrameSize - 1) + (kMaxHeldGarbage - 1);

// decode(encode(decode(f))) must encode to the same bytes as decode(f): decoders and
// Reply::toFrame agree on every layout.
void checkReply(const Frame &frame, Series series)
{
    DecodeContext ctx;
    ctx.series = series;
    const ReplyDecodeResult first = decodeReply(frame, ctx);
    require(first.reply.has_value() == (first.error == DecodeError::None));
    if (!first.reply)
        return;
    const Frame again = first.reply->toFrame();
    const ReplyDecodeResult second = decodeReply(again, ctx);
    require(second.reply.has_value());
    require(second.reply->toFrame() == again);
}

void checkFrame(const ParseEvent &ev)
{
    require(ev.frame.encode() == ev.bytes);
    require(ev.frame.direction().has_value());
    const RequestDecodeResult req = decodeRequest(ev.frame);
    require(req.request.has_value() == (req.error == DecodeError::None));
    if (req.request) {
        const Frame again = req.request->toFrame();
        require(again.command == ev.frame.command && again.id == ev.frame.id);
        require(again.data.size() == ev.frame.data.size());
    }
    checkReply(ev.frame, Series::MS);
    checkReply(ev.frame, Series::MF);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    // The first byte picks the chunk size (1..256) so that split points are explored too.
    const size_t chunk = size_t(data[0]) + 1;
    const char *bytes = reinterpret_cast<const char *>(data + 1);
    const size_t n = size - 1;

    size_t offset = 0;
    const StreamParser::Sink sink = [&](const ParseEvent &ev) {
        // Every byte reported exactly once, in order.
        require(!ev.bytes.isEmpty());
        require(offset + size_t(ev.bytes.size()) <= n);
        require(std::memcmp(ev.bytes.constData(), bytes + offset, size_t(ev.bytes.size())) == 0);
        offset += size_t(ev.bytes.size());
        if (ev.isFrame)
            checkFrame(ev);
        else if (ev.error == ParseError::UnknownCommand || ev.error == ParseError::BadLength)
            (void)decodeReply(ev.frame), (void)decodeRequest(ev.frame);
    };
    StreamParser parser;
    for (size_t at = 0; at < n; at += chunk) {
        parser.feed(bytes + at, qsizetype(std::min(chunk, n - at)), sink);
        require(parser.pendingBytes() <= kMaxPendingBytes);
    }
    parser.finish(sink);
    require(offset == n);
    require(parser.pendingBytes() == 0);
    return 0;
}
