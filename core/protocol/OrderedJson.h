#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QJsonValue>
#include <QtCore/QList>
#include <QtCore/QPair>
#include <QtCore/QString>

namespace lk::protocol {

/// The one JSON writer of CLI.md output: an object with its keys in the order they were added
/// (QJsonDocument sorts them), physical values written as reals ("100.0"), on one line.
class OrderedJson {
public:
    OrderedJson &integer(const QString &key, qint64 value);
    OrderedJson &real(const QString &key, double value);
    OrderedJson &text(const QString &key, const QString &value);
    OrderedJson &boolean(const QString &key, bool value);
    OrderedJson &null(const QString &key);
    /// A CLI.md fields object (reply or request fields), in the order of fieldsText().
    OrderedJson &fields(const QString &key, const QJsonObject &fields);
    /// Already-written JSON (an array, a nested OrderedJson).
    OrderedJson &raw(const QString &key, const QByteArray &json);

    QByteArray toJson() const;

    /// An object with its keys in the order of the field table (ProtocolFields), unknown
    /// keys after them, sorted; numbers under a real field's key are written as reals.
    static QByteArray fieldsText(const QJsonObject &object);
    static QByteArray realText(double value);
    static QByteArray stringText(const QString &value);

private:
    /// A value of a fields object: a number as a real or an integer as its key says.
    static QByteArray valueText(const QString &key, const QJsonValue &value);

    QList<QPair<QString, QByteArray>> m_items;
};

} // namespace lk::protocol
