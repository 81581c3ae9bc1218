#include "RecordTraffic.h"

#include "RecordedFrameParser.h"

#include <QtCore/QCoreApplication>

namespace lk::recording {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("lk::recording", text);
}

QString noteOf(const RecordEvent &r)
{
    if (r.kind == RecordEvent::Kind::Dropped)
        return tr("Recorder dropped %1 bytes in %2 chunks (the disk could not keep up)")
            .arg(r.droppedBytes)
            .arg(r.droppedChunks);
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

bus::TrafficEvent trafficEventOf(const RecordedFrame &f)
{
    bus::TrafficEvent e;
    e.time = double(f.timeNs) * 1e-9;
    e.bytes = f.event.bytes;
    e.id = f.event.frame.id;
    e.command = f.event.frame.command;
    if (f.event.isFrame) {
        e.kind = f.transmitted ? bus::TrafficEvent::Kind::Sent : bus::TrafficEvent::Kind::Frame;
        e.frame = f.event.frame;
        e.context = f.context;
    } else {
        e.kind = bus::TrafficEvent::Kind::Fault;
        e.error = f.event.error;
    }
    return e;
}

std::optional<bus::TrafficEvent> noteEventOf(const RecordEvent &r)
{
    if (r.kind != RecordEvent::Kind::Link && r.kind != RecordEvent::Kind::Dropped)
        return std::nullopt;
    bus::TrafficEvent e;
    e.kind = bus::TrafficEvent::Kind::Note;
    e.time = double(r.timeNs) * 1e-9;
    e.text = noteOf(r);
    return e;
}

bus::TrafficBatch trafficEventsOf(const QVector<RecordEvent> &records, ContextSnapshot context)
{
    bus::TrafficBatch out;
    RecordedFrameParser parser(std::move(context));
    const auto sink = [&out](const RecordedFrame &f) { out.append(trafficEventOf(f)); };
    for (const RecordEvent &r : records) {
        parser.feed(r, sink);
        if (std::optional<bus::TrafficEvent> note = noteEventOf(r))
            out.append(std::move(*note));
    }
    parser.finish(sink);
    return out;
}

} // namespace lk::recording
