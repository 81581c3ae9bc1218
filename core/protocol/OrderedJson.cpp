#include "OrderedJson.h"

#include "ProtocolFields.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QLocale>
#include <QtCore/QVariant>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace lk::protocol {

QByteArray OrderedJson::realText(double value)
{
    if (!std::isfinite(value))
        return QByteArrayLiteral("null"); // JSON has no NaN; no field ever produces one
    QByteArray t = QByteArray::number(value, 'g', QLocale::FloatingPointShortest);
    if (!t.contains('.') && !t.contains('e'))
        t += ".0";
    return t;
}

QByteArray OrderedJson::stringText(const QString &value)
{
    // Keys, names and hex are plain ASCII: quote them directly.
    const bool plain = std::all_of(value.cbegin(), value.cend(), [](QChar c) {
        return c.unicode() >= 0x20 && c.unicode() < 0x7F && c != QLatin1Char('"') &&
               c != QLatin1Char('\\');
    });
    if (plain)
        return '"' + value.toLatin1() + '"';
    // Anything else: let QJsonDocument escape it in a one-element array, brackets dropped.
    const QByteArray a = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return a.mid(1, a.size() - 2);
}

QByteArray OrderedJson::valueText(const QString &key, const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Bool:
        return v.toBool() ? QByteArrayLiteral("true") : QByteArrayLiteral("false");
    case QJsonValue::Double: {
        if (ProtocolFields::isReal(key))
            return realText(v.toDouble());
        if (v.toVariant().typeId() == QMetaType::LongLong)
            return QByteArray::number(v.toInteger());
        const double d = v.toDouble();
        return std::isfinite(d) ? QByteArray::number(d, 'g', QLocale::FloatingPointShortest)
                                : QByteArrayLiteral("null");
    }
    case QJsonValue::String:
        return stringText(v.toString());
    case QJsonValue::Array: {
        QByteArray out = "[";
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < a.size(); ++i) {
            if (i > 0)
                out += ',';
            out += valueText(key, a.at(i));
        }
        return out + ']';
    }
    case QJsonValue::Object:
        return fieldsText(v.toObject());
    case QJsonValue::Null:
    case QJsonValue::Undefined:
        break;
    }
    return QByteArrayLiteral("null");
}

QByteArray OrderedJson::fieldsText(const QJsonObject &object)
{
    // Rank each key once; keys() is sorted, so unknown keys stay sorted after the known ones.
    std::vector<std::pair<int, QString>> keys;
    keys.reserve(size_t(object.size()));
    for (const QString &k : object.keys())
        keys.emplace_back(ProtocolFields::rank(k), k);
    std::stable_sort(keys.begin(), keys.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    OrderedJson o;
    for (const auto &[rank, key] : keys)
        o.raw(key, valueText(key, object.value(key)));
    return o.toJson();
}

OrderedJson &OrderedJson::integer(const QString &key, qint64 value)
{
    m_items.append({key, QByteArray::number(value)});
    return *this;
}

OrderedJson &OrderedJson::real(const QString &key, double value)
{
    m_items.append({key, realText(value)});
    return *this;
}

OrderedJson &OrderedJson::text(const QString &key, const QString &value)
{
    m_items.append({key, stringText(value)});
    return *this;
}

OrderedJson &OrderedJson::boolean(const QString &key, bool value)
{
    m_items.append({key, value ? QByteArrayLiteral("true") : QByteArrayLiteral("false")});
    return *this;
}

OrderedJson &OrderedJson::null(const QString &key)
{
    m_items.append({key, QByteArrayLiteral("null")});
    return *this;
}

OrderedJson &OrderedJson::fields(const QString &key, const QJsonObject &fields)
{
    m_items.append({key, fieldsText(fields)});
    return *this;
}

OrderedJson &OrderedJson::raw(const QString &key, const QByteArray &json)
{
    m_items.append({key, json});
    return *this;
}

QByteArray OrderedJson::toJson() const
{
    QByteArray out;
    out.reserve(160);
    out += '{';
    for (qsizetype i = 0; i < m_items.size(); ++i) {
        if (i > 0)
            out += ',';
        out += stringText(m_items.at(i).first);
        out += ':';
        out += m_items.at(i).second;
    }
    out += '}';
    return out;
}

} // namespace lk::protocol
