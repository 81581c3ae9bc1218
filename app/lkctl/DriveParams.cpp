#include "DriveParams.h"

#include "LiveBus.h"

#include <protocol/RequestBuilder.h>
#include <record/ParameterFields.h>

namespace lk::lkctl {

using protocol::ParameterValue;
using protocol::ParamId;
using protocol::ParamLayout;
using protocol::ParamTable;

const QList<DriveParam> &DriveParams::all()
{
    static const QList<DriveParam> kAll = [] {
        QList<DriveParam> list;
        for (const protocol::ParamInfo &info : ParamTable::all()) {
            if (info.id == ParamId::MaxAngleHigh)
                continue; // the second half of max_angle_deg
            DriveParam p;
            p.fields = protocol::ProtocolFields::ofParam(info.id);
            p.ids = {info.id};
            if (info.id == ParamId::MaxAngleLow)
                p.ids.append(ParamId::MaxAngleHigh);
            // A loop keeps the table's name (its fields are angle_kp ...); a value is named
            // as info's `params` shows it.
            p.name = info.layout == ParamLayout::Pid ? QString::fromLatin1(info.name)
                                                     : p.fields.first().name;
            list.append(p);
        }
        return list;
    }();
    return kAll;
}

std::optional<DriveParam> DriveParams::find(const QString &name)
{
    for (const DriveParam &p : all()) {
        if (p.name == name)
            return p;
    }
    return std::nullopt;
}

QString DriveParams::names()
{
    QStringList n;
    for (const DriveParam &p : all())
        n << p.name;
    return n.join(QStringLiteral(", "));
}

QString DriveParams::helpLines(const QString &indent)
{
    QString text;
    for (const DriveParam &p : all()) {
        QString values;
        if (p.isLoop()) {
            QStringList gains;
            for (const protocol::FieldSpec &f : p.fields)
                gains << f.name.section(QLatin1Char('_'), -1).toUpper();
            values = gains.join(QLatin1Char(' ')) + QStringLiteral(", each ");
        }
        text +=
            indent + p.name.leftJustified(17) + values + p.fields.first().range + QLatin1Char('\n');
    }
    return text;
}

std::optional<QList<ParameterValue>> DriveParams::read(LiveBus &bus, int id,
                                                       const DriveParam &param)
{
    QList<ParameterValue> values;
    for (ParamId p : param.ids) {
        const bus::RequestResult r = bus.request(*protocol::build::readParam(id, p).request);
        const ParameterValue *v =
            r.reply ? std::get_if<ParameterValue>(&r.reply->payload) : nullptr;
        if (!r.ok() || !v) {
            bus.reportFailure(r);
            return std::nullopt;
        }
        if (v->paramId != quint8(p)) {
            bus.error(QStringLiteral("drive %1 answered read_param %2 with parameter 0x%3")
                          .arg(id)
                          .arg(ParamTable::name(p))
                          .arg(v->paramId, 2, 16, QLatin1Char('0')));
            return std::nullopt;
        }
        values.append(*v);
    }
    return values;
}

bool DriveParams::readFields(LiveBus &bus, int id, const DriveParam &param, QJsonObject &into)
{
    const std::optional<QList<ParameterValue>> values = read(bus, id, param);
    if (!values)
        return false;
    const QJsonObject fields = record::ParameterFields::of(*values);
    for (auto it = fields.begin(); it != fields.end(); ++it)
        into.insert(it.key(), it.value());
    return true;
}

bool DriveParams::readAll(LiveBus &bus, int id, QJsonObject &pid, QJsonObject &params)
{
    bool ok = true;
    for (const DriveParam &p : all())
        ok &= readFields(bus, id, p, p.isLoop() ? pid : params);
    return ok;
}

QString DriveParams::noTableMessage(int id, const QString &what)
{
    return QStringLiteral("drive %1 runs firmware before 2.35 (protocol V2.3), which has no "
                          "parameter table (read_param/write_param_*), so it cannot %2; nothing "
                          "was sent. On V2.3 use 'lkctl read %1 pid' and 'lkctl read %1 accel' "
                          "(read_pid, read_accel), or 'lkctl write %1 pid ...' and "
                          "'lkctl write %1 accel ...'")
        .arg(id)
        .arg(what);
}

} // namespace lk::lkctl
