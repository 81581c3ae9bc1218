#pragma once

#include <protocol/Series.h>
#include <protocol/StreamParser.h>

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>
#include <QtCore/QVector>

namespace lk::bus {

/// One entry of the traffic view: bytes sent, a frame or fault received, or a note.
/// A Sent or Frame event carries its frame as parsed on the bus thread and the decode context
/// its ID had at that moment, so the view formats it without parsing again, and a row keeps
/// its meaning when a drive's series is learnt or changed later.
struct TrafficEvent {
    enum class Kind {
        Sent,    ///< bytes written to the transport (one request)
        Frame,   ///< a valid frame received
        Fault,   ///< bytes received that did not form a valid frame (see `error`)
        Timeout, ///< the attempt for (id, command) got no reply
        Note,    ///< connection changes, dropped events
    };
    Kind kind = Kind::Note;
    double time = 0; ///< seconds since the session started
    /// The wire bytes (hex column, export). On CAN (context.link) one CanRecord per frame:
    /// CanRecord::decode(bytes)->candumpText() gives "141#9C00000000000000".
    QByteArray bytes;
    protocol::ParseError error = protocol::ParseError::Garbage; ///< Fault only
    int id = 0;            ///< Sent/Frame/Timeout; 0 when unknown
    quint8 command = 0;    ///< Sent/Frame/Timeout
    QString text;          ///< Note text
    protocol::Frame frame; ///< Sent/Frame: the frame `bytes` hold, parsed once on the bus thread
    protocol::DecodeContext context; ///< Sent/Frame: how `id` decoded when the event happened
};

using TrafficBatch = QVector<TrafficEvent>;

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::TrafficEvent)
Q_DECLARE_METATYPE(lk::bus::TrafficBatch)
