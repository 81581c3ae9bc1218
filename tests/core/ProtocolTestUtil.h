#pragma once

#include "protocol/StreamParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

#include <vector>

namespace lk::test {

/// Helpers shared by the protocol tests: hex vectors and a parser event collector.

/// "3E 80 01 00 BF" -> bytes. Vectors in the tests are written by hand from the spec and
/// docs/ERRATA.md (checked with an independent script), never produced by the code under test.
inline QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

/// Bytes -> "3E 80 01 00 BF", for readable failure messages.
inline QString spaced(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

/// Feeds a parser and keeps every event it reports, in order.
struct EventLog {
    std::vector<protocol::ParseEvent> events;
    protocol::StreamParser::Sink sink()
    {
        return [this](const protocol::ParseEvent &ev) { events.push_back(ev); };
    }
    /// The concatenation of the bytes of every event: must equal the input.
    QByteArray allBytes() const
    {
        QByteArray out;
        for (const auto &ev : events)
            out.append(ev.bytes);
        return out;
    }
    int frameCount() const
    {
        int n = 0;
        for (const auto &ev : events)
            n += ev.isFrame ? 1 : 0;
        return n;
    }
};

/// Parses a whole stream in one feed plus finish().
inline EventLog parseAll(const QByteArray &stream)
{
    EventLog log;
    protocol::StreamParser parser;
    parser.feed(stream, log.sink());
    parser.finish(log.sink());
    return log;
}

/// A one-line description of an event: "frame 3E 80 01 00 BF" or "garbage AA 55".
inline QString describe(const protocol::ParseEvent &ev)
{
    const QString kind = ev.isFrame ? QStringLiteral("frame")
                                    : QString::fromLatin1(protocol::parseErrorName(ev.error));
    return kind + QLatin1Char(' ') + spaced(ev.bytes);
}

/// The data lengths of one command, by hand from CLI.md and docs/ERRATA.md (not from the table
/// under test): the request LEN and every LEN a reply may carry (echoes included).
struct CommandLengths {
    const char *name;
    int code;
    int request;
    QList<int> replies;
};

inline const CommandLengths kCommandLengths[] = {
    {"read_pid", 0x30, 0, {6}},
    {"write_pid_ram", 0x31, 6, {6}},
    {"write_pid_rom", 0x32, 6, {6}},
    {"read_accel", 0x33, 0, {4}},
    {"write_accel_ram", 0x34, 4, {4}},
    {"read_encoder", 0x90, 0, {6}},
    {"write_encoder_offset", 0x91, 2, {2}},
    {"write_zero_rom", 0x19, 0, {0, 2}}, // ERRATA: echo, or uint16 zero on newer firmware
    {"read_multi_turn", 0x92, 0, {8}},
    {"read_single_turn", 0x94, 0, {4}},
    {"clear_angle", 0x95, 0, {0}},
    {"read_state1", 0x9A, 0, {7}},
    {"clear_errors", 0x9B, 0, {7}},
    {"read_state2", 0x9C, 0, {7}},
    {"read_state3", 0x9D, 0, {7}},
    {"motor_off", 0x80, 0, {0}},
    {"motor_stop", 0x81, 0, {0}},
    {"motor_run", 0x88, 0, {0}},
    {"open_loop", 0xA0, 2, {7}},
    {"torque", 0xA1, 2, {7}},
    {"speed", 0xA2, 4, {7}},
    {"multi_position", 0xA3, 8, {7}},
    {"multi_position_limited", 0xA4, 12, {7}},
    {"single_position", 0xA5, 4, {7}},
    {"single_position_limited", 0xA6, 8, {7}},
    {"increment_position", 0xA7, 4, {7}},         // ERRATA: LEN 4, not 3
    {"increment_position_limited", 0xA8, 8, {7}}, // ERRATA: reply LEN 7, not 8
    {"read_model", 0x12, 0, {42, 58}},            // V2.3 and V2.35 layouts
};

} // namespace lk::test
