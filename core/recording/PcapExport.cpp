#include "PcapExport.h"

#include "CandumpLog.h"
#include "RecordEncoder.h"
#include "RecordedFrameParser.h"
#include "Varint.h"

namespace lk::recording {

QByteArray PcapExport::fileHeader(quint32 linkType)
{
    QByteArray h;
    varint::putFixed<quint32>(h, 0xA1B2C3D4u); // microsecond timestamps, little-endian
    varint::putFixed<quint16>(h, 2);
    varint::putFixed<quint16>(h, 4);
    varint::putFixed<qint32>(h, 0);      // thiszone
    varint::putFixed<quint32>(h, 0);     // sigfigs
    varint::putFixed<quint32>(h, 65535); // snaplen
    varint::putFixed<quint32>(h, linkType);
    return h;
}

QByteArray PcapExport::socketCanPacket(qint64 unixNs, const protocol::CanRecord &record)
{
    constexpr quint32 kEffFlag = 0x80000000u; // CAN_EFF_FLAG
    constexpr quint32 kErrFlag = 0x20000000u; // CAN_ERR_FLAG
    quint32 id = record.canId;
    if (record.isError())
        id |= kErrFlag;
    else if (record.isExtended())
        id |= kEffFlag;
    QByteArray frame;
    frame.append(char(id >> 24)).append(char(id >> 16)).append(char(id >> 8)).append(char(id));
    frame.append(char(record.data.size()));
    frame.append(3, '\0');
    frame.append(record.data.leftJustified(protocol::CanRecord::kMaxData, '\0', true));
    QByteArray p;
    const qint64 us = unixNs / 1000;
    varint::putFixed<quint32>(p, quint32(us / 1'000'000));
    varint::putFixed<quint32>(p, quint32(us % 1'000'000));
    varint::putFixed<quint32>(p, quint32(frame.size()));
    varint::putFixed<quint32>(p, quint32(frame.size()));
    return p + frame;
}

namespace {

qint64 writeSocketCan(RecordingReader &reader, QIODevice &out)
{
    const qint64 startNs = reader.header().wallClockStartMs * 1'000'000;
    out.write(PcapExport::fileHeader(PcapExport::kLinkTypeSocketCan));
    qint64 packets = 0;
    CandumpLog::forEachFrame(reader, [&](qint64 timeNs, const protocol::CanRecord &r) {
        out.write(PcapExport::socketCanPacket(startNs + timeNs, r));
        ++packets;
    });
    return packets;
}

} // namespace

QByteArray PcapExport::packet(qint64 unixNs, bool transmitted, FrameKind kind,
                              const QByteArray &bytes)
{
    QByteArray p;
    const qint64 us = unixNs / 1000;
    const quint32 length = quint32(bytes.size() + 2);
    varint::putFixed<quint32>(p, quint32(us / 1'000'000));
    varint::putFixed<quint32>(p, quint32(us % 1'000'000));
    varint::putFixed<quint32>(p, length);
    varint::putFixed<quint32>(p, length);
    p.append(char(transmitted ? 1 : 0));
    p.append(char(kind));
    p.append(bytes);
    return p;
}

qint64 PcapExport::write(RecordingReader &reader, QIODevice &out)
{
    if (linkOf(reader.header()) == protocol::Link::Can)
        return writeSocketCan(reader, out);
    const qint64 startNs = reader.header().wallClockStartMs * 1'000'000;
    qint64 packets = 0;
    out.write(fileHeader());
    RecordedFrameParser parser(reader.header().context, linkOf(reader.header()));
    const auto sink = [&](const RecordedFrame &f) {
        FrameKind kind = FrameKind::NoFrame;
        if (f.event.isFrame)
            kind = f.event.direction == protocol::FrameDirection::Reply  ? FrameKind::Reply
                   : f.event.direction == protocol::FrameDirection::Echo ? FrameKind::Echo
                                                                         : FrameKind::Request;
        out.write(packet(startNs + f.timeNs, f.transmitted, kind, f.event.bytes));
        ++packets;
    };
    const auto context = [&](qint64 timeNs, const ContextSnapshot &snapshot) {
        QByteArray triples;
        RecordEncoder::putContext(triples, snapshot);
        // The encoder's count prefix is one varint byte for up to 127 drives: drop it. The
        // dissector reads (id, series, generation) triples only: the list of drives the user
        // chose, after them, is left out.
        out.write(packet(startNs + timeNs, false, FrameKind::Context,
                         triples.mid(1, 3 * snapshot.size())));
        ++packets;
    };
    context(0, reader.header().context);
    RecordEvent e;
    while (reader.next(&e)) {
        parser.feed(e, sink);
        if (e.kind == RecordEvent::Kind::Context)
            context(e.timeNs, e.context);
    }
    parser.finish(sink);
    return packets;
}

} // namespace lk::recording
