#include "ReplyText.h"

#include <protocol/ErrorFlags.h>
#include <protocol/ProtocolFields.h>

#include <QtCore/QList>

#include <algorithm>

namespace lk::lkctl {

namespace {

using protocol::ProtocolField;

/// The rows lkctl's text mode shows, in CLI.md order: the labelled rows of the field table.
const QList<const ProtocolField *> &shownFields()
{
    static const QList<const ProtocolField *> kShown = [] {
        QList<const ProtocolField *> rows;
        for (const ProtocolField &f : protocol::ProtocolFields::all()) {
            if (f.label)
                rows.append(&f);
        }
        return rows;
    }();
    return kShown;
}

QString valueText(const ProtocolField &l, const QJsonValue &v, const QJsonObject &fields)
{
    if (QLatin1String(l.name) == QLatin1String("error_state"))
        return ReplyText::errorText(v.toInt(), fields);
    if (QLatin1String(l.name) == QLatin1String("voltage_v") &&
        fields.contains(QStringLiteral("bus_current_a")))
        return QString::number(v.toDouble(), 'f', 2) + QStringLiteral(" V");
    if (v.isString())
        return v.toString();
    if (v.isBool())
        return v.toBool() ? QStringLiteral("yes") : QStringLiteral("no");
    QString n = QString::number(v.toInteger());
    if (l.places >= 0)
        n = l.trim ? ReplyText::number(v.toDouble(), l.places)
                   : QString::number(v.toDouble(), 'f', l.places);
    if (QByteArray(l.name).endsWith("_version") && !n.contains(QLatin1Char('.')))
        n += QStringLiteral(".0"); // "1.0", as the vendor's tools show versions
    return *l.textUnit ? n + QLatin1Char(' ') + QString::fromUtf8(l.textUnit) : n;
}

} // namespace

QString ReplyText::number(double value, int decimals)
{
    QString t = QString::number(value, 'f', decimals);
    if (t.contains(QLatin1Char('.'))) {
        while (t.endsWith(QLatin1Char('0')))
            t.chop(1);
        if (t.endsWith(QLatin1Char('.')))
            t.chop(1);
    }
    return t == QLatin1String("-0") ? QStringLiteral("0") : t;
}

QString ReplyText::errorText(int errorState, protocol::Generation generation)
{
    const QStringList flags = protocol::ErrorFlags::words(quint8(errorState), generation);
    if (flags.isEmpty())
        return QStringLiteral("none");
    return QStringLiteral("%1 (0x%2)")
        .arg(flags.join(QStringLiteral(", ")))
        .arg(errorState, 2, 16, QLatin1Char('0'));
}

QString ReplyText::errorText(int errorState, const QJsonObject &fields)
{
    // read_state1's fields name every flag of the drive's generation (FieldJson): eight
    // keys from a V2.35 drive, two from a V2.3 one. Their presence tells the generation.
    const bool v235 = fields.contains(QStringLiteral("bus_current_a"));
    return errorText(errorState, v235 ? protocol::Generation::V2_35 : protocol::Generation::V2_3);
}

QStringList ReplyText::lines(const QJsonObject &fields, const QString &indent)
{
    return lines(QList<QJsonObject>{fields}, indent);
}

QStringList ReplyText::lines(const QList<QJsonObject> &groups, const QString &indent)
{
    qsizetype width = 0;
    for (const QJsonObject &fields : groups) {
        for (const ProtocolField *f : shownFields()) {
            if (fields.contains(QLatin1String(f->name)))
                width = std::max(width, qsizetype(qstrlen(f->label)));
        }
    }
    QStringList out;
    for (const QJsonObject &fields : groups) {
        for (const ProtocolField *f : shownFields()) {
            const QJsonValue v = fields.value(QLatin1String(f->name));
            if (v.isUndefined())
                continue;
            out << indent + QString::fromLatin1(f->label).leftJustified(width + 2) +
                       valueText(*f, v, fields);
        }
    }
    return out;
}

QString ReplyText::oneLine(const QJsonObject &fields)
{
    QStringList parts;
    for (const QString &line : lines(fields))
        parts << line.simplified();
    return parts.join(QStringLiteral(", "));
}

} // namespace lk::lkctl
