#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QPair>
#include <QtCore/QString>

namespace lk::lkctl {

/// One JSON object written with its keys in the order they were added (QJsonDocument sorts
/// them). Physical values are written as reals ("100.0"), like FieldJson::toJsonLine.
class OrderedJson {
public:
    OrderedJson &integer(const QString &key, qint64 value);
    OrderedJson &real(const QString &key, double value);
    OrderedJson &text(const QString &key, const QString &value);
    OrderedJson &boolean(const QString &key, bool value);
    OrderedJson &null(const QString &key);
    /// A CLI.md fields object (reply or request fields), in FieldJson's key order.
    OrderedJson &fields(const QString &key, const QJsonObject &fields);
    /// Already-written JSON (an array, a nested OrderedJson).
    OrderedJson &raw(const QString &key, const QByteArray &json);

    QByteArray toJson() const;

    static QByteArray realText(double value);
    static QByteArray stringText(const QString &value);

private:
    QList<QPair<QString, QByteArray>> m_items;
};

} // namespace lk::lkctl
