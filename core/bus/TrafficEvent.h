#pragma once

#include <protocol/StreamParser.h>

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>
#include <QtCore/QVector>

namespace lk::bus {

/// One entry of the traffic view: bytes sent, a frame or fault received, or a note.
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
    QByteArray bytes;
    protocol::ParseError error = protocol::ParseError::Garbage; ///< Fault only
    int id = 0;         ///< Sent/Frame/Timeout; 0 when unknown
    quint8 command = 0; ///< Sent/Frame/Timeout
    QString text;       ///< Note text
};

using TrafficBatch = QVector<TrafficEvent>;

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::TrafficEvent)
Q_DECLARE_METATYPE(lk::bus::TrafficBatch)
