#pragma once

#include "CanRecord.h"
#include "FrameParser.h"

#include <QtCore/QByteArray>

#include <functional>

namespace lk::protocol {

/// The CAN FrameParser: cuts the CAN transport's records (CanRecord) out of the byte stream
/// and turns each drive frame into a ParseEvent with Frame{B0, drive ID, B1..B7}.
///
/// Direction: at the host end an echoed record is our own request, anything else on a drive's
/// ID is its reply (or echo, for commands whose reply repeats the request); at the drive end
/// what arrives on 0x140+ID is a request. A record with a DLC other than 8 is BadLength, an
/// unknown B0 UnknownCommand (both carry the frame); a record that is not of this version is
/// Garbage. Frames that are no drive's (other devices on the bus, the 0x280 multi-motor frame)
/// and error frames are not ParseEvents: they go to their own sinks, as they are not faults
/// of the LK protocol.
class CanRecordParser : public FrameParser {
public:
    using RecordSink = std::function<void(const CanRecord &)>;

    explicit CanRecordParser(LinkEnd end = LinkEnd::Host) : m_end(end) {}

    using FrameParser::feed;
    void feed(const char *data, qsizetype size, const Sink &sink) override;
    /// A partial record left at the end is reported as Truncated.
    void finish(const Sink &sink) override;
    void reset() override { m_buf.clear(); }
    qsizetype pendingBytes() const override { return m_buf.size(); }

    /// Error frames (the transport reads the bus state from them too).
    void setErrorFrameSink(RecordSink sink) { m_errorSink = std::move(sink); }
    /// Data frames on IDs that are no drive's, 0x280 included.
    void setOtherFrameSink(RecordSink sink) { m_otherSink = std::move(sink); }
    quint64 errorFrames() const { return m_errorFrames; }
    quint64 otherFrames() const { return m_otherFrames; }

private:
    void handle(const CanRecord &record, const QByteArray &bytes, const Sink &sink);
    FrameDirection directionOf(const CanRecord &record, const Frame &frame, can::IdBase base) const;

    LinkEnd m_end;
    QByteArray m_buf;
    RecordSink m_errorSink;
    RecordSink m_otherSink;
    quint64 m_errorFrames = 0;
    quint64 m_otherFrames = 0;
};

} // namespace lk::protocol
