#pragma once

#include "protocol/Frame.h"
#include "protocol/Reply.h"
#include "protocol/Request.h"
#include "protocol/RequestBuilder.h"
#include "protocol/StreamParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtTest/QTest>

#include <optional>

namespace lk::test {

/// "3E 9C 01 00 DB" -> bytes (vectors are written by hand from the spec, not by the code).
inline QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

inline QString spaced(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

/// A request from a builder that must succeed (test input, not code under test).
inline protocol::Request req(const protocol::BuildResult &r)
{
    if (!r.ok())
        qFatal("test request refused: %s", qPrintable(r.error.message()));
    return *r.request;
}

/// The typed payload of a reply that must exist and carry T; aborts the test otherwise
/// (a clear message instead of a crash on a null optional).
template <typename T> T payloadOf(const std::optional<protocol::Reply> &reply)
{
    if (!reply)
        qFatal("expected a reply, got none");
    if (!std::holds_alternative<T>(reply->payload))
        qFatal("reply to 0x%02X carries another payload type", unsigned(reply->command));
    return std::get<T>(reply->payload);
}

/// Every parse event of a byte stream, in order (end of stream included).
inline QList<protocol::ParseEvent> parseAll(const QByteArray &bytes)
{
    QList<protocol::ParseEvent> out;
    protocol::StreamParser parser;
    auto sink = [&](const protocol::ParseEvent &e) { out.append(e); };
    parser.feed(bytes, sink);
    parser.finish(sink);
    return out;
}

} // namespace lk::test
