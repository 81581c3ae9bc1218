#include "CanRecordParser.h"

#include "Command.h"
#include "StreamParser.h"

namespace lk::protocol {

void CanRecordParser::feed(const char *data, qsizetype size, const Sink &sink)
{
    m_buf.append(data, size);
    qsizetype at = 0;
    for (; m_buf.size() - at >= CanRecord::kSize; at += CanRecord::kSize) {
        // A copy of its own: mid() of a buffer holding one record shares the whole buffer.
        const QByteArray bytes(m_buf.constData() + at, CanRecord::kSize);
        if (const std::optional<CanRecord> record = CanRecord::decode(bytes.constData())) {
            handle(*record, bytes, sink);
            continue;
        }
        ParseEvent ev;
        ev.error = ParseError::Garbage;
        ev.bytes = bytes;
        sink(ev);
    }
    m_buf.remove(0, at);
}

void CanRecordParser::finish(const Sink &sink)
{
    if (m_buf.isEmpty())
        return;
    ParseEvent ev;
    ev.error = ParseError::Truncated;
    ev.bytes = m_buf;
    m_buf.clear();
    sink(ev);
}

void CanRecordParser::handle(const CanRecord &record, const QByteArray &bytes, const Sink &sink)
{
    if (record.isError()) {
        ++m_errorFrames;
        if (m_errorSink)
            m_errorSink(record);
        return;
    }
    const std::optional<can::DriveAddress> address =
        record.isExtended() ? std::nullopt : can::driveAddressOf(record.canId);
    if (!address) {
        ++m_otherFrames;
        if (m_otherSink)
            m_otherSink(record);
        return;
    }
    ParseEvent ev;
    ev.bytes = bytes;
    ev.canId = record.canId;
    ev.echoed = record.isEcho();
    ev.frame.id = address->driveId;
    if (!record.data.isEmpty())
        ev.frame.command = static_cast<quint8>(record.data[0]);
    ev.frame.data = record.data.mid(1);
    if (record.data.size() != can::kDataSize) {
        ev.error = ParseError::BadLength;
    } else if (!CommandTable::find(ev.frame.command)) {
        ev.error = ParseError::UnknownCommand;
    } else {
        ev.isFrame = true;
        ev.direction = directionOf(record, ev.frame, address->base);
    }
    sink(ev);
}

FrameDirection CanRecordParser::directionOf(const CanRecord &record, const Frame &frame,
                                            can::IdBase base) const
{
    // An echo is the frame this end sent itself. Otherwise the host hears drives, and a
    // drive hears the host on 0x140+ID (and other V2.36 drives on 0x180+ID).
    const bool fromHost =
        m_end == LinkEnd::Host ? record.isEcho() : !record.isEcho() && base == can::IdBase::Base140;
    if (fromHost)
        return FrameDirection::Request;
    return CommandTable::find(frame.command)->replyEchoesRequest ? FrameDirection::Echo
                                                                 : FrameDirection::Reply;
}

std::unique_ptr<FrameParser> makeFrameParser(Link link, LinkEnd end)
{
    if (link == Link::Can)
        return std::make_unique<CanRecordParser>(end);
    return std::make_unique<StreamParser>();
}

} // namespace lk::protocol
