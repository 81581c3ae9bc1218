#include "OrderedJson.h"

#include <protocol/FieldJson.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QLocale>

#include <cmath>

namespace lk::lkctl {

QByteArray OrderedJson::realText(double value)
{
    if (!std::isfinite(value))
        return QByteArrayLiteral("null");
    QByteArray t = QByteArray::number(value, 'g', QLocale::FloatingPointShortest);
    if (!t.contains('.') && !t.contains('e'))
        t += ".0";
    return t;
}

QByteArray OrderedJson::stringText(const QString &value)
{
    const QByteArray a = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return a.mid(1, a.size() - 2);
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
    m_items.append({key, protocol::FieldJson::toJsonLine(fields)});
    return *this;
}

OrderedJson &OrderedJson::raw(const QString &key, const QByteArray &json)
{
    m_items.append({key, json});
    return *this;
}

QByteArray OrderedJson::toJson() const
{
    QByteArray out = "{";
    for (qsizetype i = 0; i < m_items.size(); ++i) {
        if (i > 0)
            out += ',';
        out += stringText(m_items.at(i).first) + ':' + m_items.at(i).second;
    }
    out += '}';
    return out;
}

} // namespace lk::lkctl
