#include "RecordTraffic.h"

#include <protocol/StreamParser.h>

#include <QtCore/QCoreApplication>

namespace lk::recording {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("lk::recording::RecordTraffic", text);
}

QString linkNote(const RecordEvent &r)
{
    switch (r.link) {
    case LinkEventKind::Opened:
        return tr("Opened %1").arg(r.text);
    case LinkEventKind::Closed:
        return tr("Closed %1").arg(r.text);
    case LinkEventKind::BaudChanged:
        return tr("Baud changed to %1").arg(r.baud);
    case LinkEventKind::Error:
        return tr("Link error: %1").arg(r.text);
    case LinkEventKind::Disconnected:
        return tr("Link lost: %1").arg(r.text);
    }
    return r.text;
}

} // namespace

protocol::DecodeContext decodeContextOf(const ContextSnapshot &snapshot, int id)
{
    protocol::DecodeContext c;
    for (const DriveContext &d : snapshot) {
        if (d.id != id)
            continue;
        c.series = d.series.value_or(protocol::Series::MF);
        c.generation = d.generation;
    }
    return c;
}

bus::TrafficBatch trafficEventsOf(const QVector<RecordEvent> &records, ContextSnapshot context)
{
    bus::TrafficBatch out;
    protocol::StreamParser rxParser;
    protocol::StreamParser txParser;
    double time = 0;
    bool sent = false;
    const auto sink = [&](const protocol::ParseEvent &p) {
        bus::TrafficEvent e;
        e.time = time;
        e.bytes = p.bytes;
        if (p.isFrame) {
            e.kind = sent ? bus::TrafficEvent::Kind::Sent : bus::TrafficEvent::Kind::Frame;
            e.frame = p.frame;
            e.id = p.frame.id;
            e.command = p.frame.command;
            e.context = decodeContextOf(context, p.frame.id);
        } else {
            e.kind = bus::TrafficEvent::Kind::Fault;
            e.error = p.error;
            e.id = p.frame.id;
            e.command = p.frame.command;
        }
        out.append(std::move(e));
    };
    for (const RecordEvent &r : records) {
        time = double(r.timeNs) * 1e-9;
        switch (r.kind) {
        case RecordEvent::Kind::Rx:
            sent = false;
            rxParser.feed(r.bytes, sink);
            break;
        case RecordEvent::Kind::Tx:
            sent = true;
            txParser.feed(r.bytes, sink);
            break;
        case RecordEvent::Kind::Context:
            context = r.context;
            break;
        case RecordEvent::Kind::Link:
        case RecordEvent::Kind::Dropped: {
            if (r.kind == RecordEvent::Kind::Link && r.link != LinkEventKind::Error) {
                // A link that closes or reopens ends both streams: what was pending is said.
                sent = true;
                txParser.finish(sink);
                sent = false;
                rxParser.finish(sink);
            }
            bus::TrafficEvent e;
            e.kind = bus::TrafficEvent::Kind::Note;
            e.time = time;
            e.text = r.kind == RecordEvent::Kind::Link
                         ? linkNote(r)
                         : tr("Recorder dropped %1 bytes in %2 chunks (the disk could not keep "
                              "up)")
                               .arg(r.droppedBytes)
                               .arg(r.droppedChunks);
            out.append(std::move(e));
            break;
        }
        }
    }
    sent = true;
    txParser.finish(sink);
    sent = false;
    rxParser.finish(sink);
    return out;
}

} // namespace lk::recording
