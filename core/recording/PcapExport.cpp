#include "PcapExport.h"

#include "RecordEncoder.h"
#include "RecordedFrameParser.h"
#include "Varint.h"

namespace lk::recording {

QByteArray PcapExport::fileHeader()
{
    QByteArray h;
    varint::putFixed<quint32>(h, 0xA1B2C3D4u); // microsecond timestamps, little-endian
    varint::putFixed<quint16>(h, 2);
    varint::putFixed<quint16>(h, 4);
    varint::putFixed<qint32>(h, 0);      // thiszone
    varint::putFixed<quint32>(h, 0);     // sigfigs
    varint::putFixed<quint32>(h, 65535); // snaplen
    varint::putFixed<quint32>(h, kLinkType);
    return h;
}

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
        // The encoder's count prefix is one varint byte for up to 127 drives: drop it.
        out.write(packet(startNs + timeNs, false, FrameKind::Context, triples.mid(1)));
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
