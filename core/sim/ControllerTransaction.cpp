#include "ControllerTransaction.h"

#include "protocol/Command.h"
#include "protocol/FieldJson.h"
#include "protocol/OrderedJson.h"

#include <cmath>

namespace lk::sim {

namespace {
/// Microseconds are what a tap can tell apart; more digits would only be noise in the log.
double toMicroseconds(double seconds)
{
    return std::round(seconds * 1e6) / 1e6;
}
} // namespace

const char *ControllerTransaction::outcomeName(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Answered:
        return "answered";
    case Outcome::Unanswered:
        return "unanswered";
    case Outcome::Dropped:
        return "dropped";
    case Outcome::Garbled:
        return "garbled";
    case Outcome::Collided:
        return "collided";
    }
    return "unanswered";
}

QByteArray ControllerTransaction::toJsonLine() const
{
    using protocol::CommandTable;
    protocol::OrderedJson json;
    json.real(QStringLiteral("time_s"), toMicroseconds(requestS))
        .integer(QStringLiteral("id"), request.id)
        .text(QStringLiteral("command"), CommandTable::name(request.command))
        .text(QStringLiteral("code"), CommandTable::codeText(static_cast<quint8>(request.command)))
        .fields(QStringLiteral("request"), protocol::FieldJson::requestFields(request, context))
        .text(QStringLiteral("outcome"), QString::fromLatin1(outcomeName(outcome)));
    if (replyEndS >= 0)
        json.real(QStringLiteral("reply_s"), toMicroseconds(replyEndS));
    if (noiseBytes > 0)
        json.integer(QStringLiteral("noise_bytes"), noiseBytes);
    if (reply)
        json.fields(QStringLiteral("reply"), protocol::FieldJson::replyFields(*reply));
    return json.toJson();
}

} // namespace lk::sim
