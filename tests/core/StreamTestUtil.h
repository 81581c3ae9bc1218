#pragma once

#include "protocol/Checksum.h"
#include "protocol/StreamParser.h"

#include "ProtocolTestUtil.h"

#include <QtCore/QRandomGenerator>
#include <QtCore/QStringList>

namespace lk::test {

/// Hand-made frames and helpers for the stream parser tests.
namespace proto = lk::protocol;
using proto::ParseError;
using proto::ParseEvent;
using proto::StreamParser;

// Hand-made frames (spec + ERRATA, checksums by hand).
inline const char *const kMotorOff = "3E 80 01 00 BF";                       // echo
inline const char *const kState2 = "3E 9C 01 07 E2 1E 00 08 0C FE FF 3F 6E"; // reply
inline const char *const kTorque = "3E A1 01 02 E2 30 F8 28";                // request
inline const char *const kPidEcho = "3E 32 20 06 96 FF FF FF FF FF FF FA";   // echo, bytes >= 0x80
inline const char *const kHeadInData = "3E 91 01 02 D2 3E 3E 7C";            // 0x3E inside the data
inline const char *const kHeadAsChecksum = "3E A1 01 02 E2 3E 00 3E";        // data checksum 0x3E
inline const char *const kMultiLimited = "3E A4 01 0C EF A0 8C 00 00 00 00 00 00 50 C3 00 00 3F";
inline const char *const kModel42 =
    "3E 12 01 2A 7B 4C 4B 2D 44 52 56 2D 4D 46 00 00 00 00 00 00 00 "
    "00 00 00 00 4D 46 34 30 31 35 76 32 2D 69 31 30 00 00 00 00 00 "
    "00 00 00 0D 17 90";
inline const char *const kZeroLen2 = "3E 19 01 02 5A 45 23 68"; // write_zero_rom reply LEN 2

inline const char *const kAllFrames[] = {kMotorOff,     kState2,     kTorque,
                                         kPidEcho,      kHeadInData, kHeadAsChecksum,
                                         kMultiLimited, kModel42,    kZeroLen2};

inline QString kindOf(const ParseEvent &ev)
{
    if (ev.isFrame)
        return QStringLiteral("frame ") + QLatin1String(proto::directionName(ev.direction));
    return QString::fromLatin1(proto::parseErrorName(ev.error));
}

/// Events as "kind: bytes" lines; adjacent garbage merged when `mergeGarbage` (garbage is
/// reported as soon as it is seen, so a chunk boundary may cut it in two).
inline QStringList lines(const std::vector<ParseEvent> &events, bool mergeGarbage)
{
    QStringList out;
    QByteArray garbage;
    const auto flush = [&] {
        if (!garbage.isEmpty())
            out << QStringLiteral("garbage: ") + spaced(garbage);
        garbage.clear();
    };
    for (const ParseEvent &ev : events) {
        if (!ev.isFrame && ev.error == ParseError::Garbage) {
            garbage.append(ev.bytes);
            if (!mergeGarbage)
                flush();
            continue;
        }
        flush();
        out << kindOf(ev) + QStringLiteral(": ") + spaced(ev.bytes);
    }
    flush();
    return out;
}

/// Checks that hold for every event of any stream; returns the first violation.
inline QString eventProblem(const ParseEvent &ev)
{
    if (ev.bytes.isEmpty())
        return QStringLiteral("empty event");
    if (ev.isFrame) {
        if (ev.frame.encode() != ev.bytes)
            return QStringLiteral("frame does not re-encode to its bytes: ") + spaced(ev.bytes);
        if (!ev.frame.direction() || *ev.frame.direction() != ev.direction)
            return QStringLiteral("direction mismatch: ") + spaced(ev.bytes);
        return {};
    }
    if (ev.error == ParseError::Garbage) {
        if (ev.bytes.contains(char(proto::kFrameHead)))
            return QStringLiteral("garbage holds a frame head: ") + spaced(ev.bytes);
        return {};
    }
    if (quint8(ev.bytes[0]) != proto::kFrameHead)
        return QStringLiteral("fault does not start at 0x3E: ") + spaced(ev.bytes);
    if (ev.bytes.size() > proto::kMaxFrameSize)
        return QStringLiteral("fault longer than a frame: ") + spaced(ev.bytes);
    return {};
}

inline QString streamProblem(const EventLog &log, const QByteArray &input)
{
    for (const ParseEvent &ev : log.events) {
        const QString p = eventProblem(ev);
        if (!p.isEmpty())
            return p;
    }
    if (log.allBytes() != input)
        return QStringLiteral("bytes not conserved: %1 in, %2 reported")
            .arg(input.size())
            .arg(log.allBytes().size());
    return {};
}

/// Parses `stream` cut into chunks at the given points, then finish().
inline EventLog parseChunked(const QByteArray &stream, const QList<qsizetype> &cuts)
{
    EventLog log;
    StreamParser parser;
    qsizetype from = 0;
    for (qsizetype cut : cuts) {
        parser.feed(stream.mid(from, cut - from), log.sink());
        from = cut;
    }
    parser.feed(stream.mid(from), log.sink());
    parser.finish(log.sink());
    return log;
}

inline QByteArray concat(std::initializer_list<const char *> parts)
{
    QByteArray out;
    for (const char *p : parts)
        out.append(hex(p));
    return out;
}

/// Random chunk boundaries over `size` bytes, chunks of 1..maxChunk bytes.
inline QList<qsizetype> randomCuts(QRandomGenerator &rng, qsizetype size, int maxChunk)
{
    QList<qsizetype> cuts;
    for (qsizetype at = rng.bounded(1, maxChunk + 1); at < size; at += rng.bounded(1, maxChunk + 1))
        cuts << at;
    return cuts;
}

inline QByteArray randomGarbageWithoutHead(QRandomGenerator &rng, int n)
{
    QByteArray g;
    while (g.size() < n) {
        const char c = char(rng.bounded(256));
        if (quint8(c) != proto::kFrameHead)
            g.append(c);
    }
    return g;
}

inline QString frameLine(const char *dir, const char *wire)
{
    return QStringLiteral("frame %1: %2").arg(QLatin1String(dir), spaced(hex(wire)));
}

} // namespace lk::test
