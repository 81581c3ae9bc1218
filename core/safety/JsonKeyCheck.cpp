#include "JsonKeyCheck.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QSet>

namespace lk::safety {

namespace {

// The end of the string token starting at `open` (the index of its closing quote), or -1.
qsizetype stringEnd(const QByteArray &text, qsizetype open)
{
    for (qsizetype i = open + 1; i < text.size(); ++i) {
        if (text.at(i) == '\\')
            ++i;
        else if (text.at(i) == '"')
            return i;
    }
    return -1;
}

// A string token with its escapes resolved, so that "a" and "\u0061" count as one key.
QString decodeKey(const QByteArray &token)
{
    const QJsonDocument doc = QJsonDocument::fromJson('[' + token + ']');
    return doc.isArray() ? doc.array().at(0).toString() : QString::fromUtf8(token);
}

} // namespace

std::optional<QString> JsonKeyCheck::duplicateKey(const QByteArray &json)
{
    QSet<QString> seen;
    int depth = 0;
    bool expectKey = false; // after '{' or ',' at depth 1 the next string is a key
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json.at(i);
        if (c == '"') {
            const qsizetype end = stringEnd(json, i);
            if (end < 0)
                return std::nullopt;
            if (depth == 1 && expectKey) {
                const QString key = decodeKey(json.mid(i, end - i + 1));
                if (seen.contains(key))
                    return key;
                seen.insert(key);
            }
            expectKey = false;
            i = end;
        } else if (c == '{' || c == '[') {
            ++depth;
            expectKey = depth == 1 && c == '{';
        } else if (c == '}' || c == ']') {
            --depth;
        } else if (c == ',') {
            expectKey = depth == 1;
        }
    }
    return std::nullopt;
}

} // namespace lk::safety
