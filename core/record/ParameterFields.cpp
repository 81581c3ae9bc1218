#include "ParameterFields.h"

#include <protocol/FieldJson.h>
#include <protocol/Reply.h>

namespace lk::record {

using protocol::ParameterValue;
using protocol::ParamId;

QJsonObject ParameterFields::of(const QList<ParameterValue> &values)
{
    if (values.size() == 2 && values.at(0).id() == ParamId::MaxAngleLow &&
        values.at(1).id() == ParamId::MaxAngleHigh) {
        const qint64 raw = protocol::joinMaxAngle(values.at(0), values.at(1));
        return {{QStringLiteral("max_angle_deg"), double(raw) / 100.0},
                {QStringLiteral("max_angle_raw"), raw}};
    }
    protocol::Reply r;
    r.command = protocol::Command::ReadParam;
    r.payload = values.value(0);
    QJsonObject o = protocol::FieldJson::replyFields(r);
    o.remove(QStringLiteral("param")); // the caller names the parameter
    o.remove(QStringLiteral("param_id"));
    return o;
}

void ParameterFields::split(const QVector<ParameterValue> &values, QJsonObject &pid,
                            QJsonObject &params)
{
    const auto find = [&values](ParamId id) -> const ParameterValue * {
        for (const ParameterValue &v : values) {
            if (v.id() == id)
                return &v;
        }
        return nullptr;
    };
    for (const protocol::ParamInfo &info : protocol::ParamTable::all()) {
        const ParameterValue *v = find(info.id);
        if (!v || info.id == ParamId::MaxAngleHigh)
            continue;
        QList<ParameterValue> read{*v};
        if (info.id == ParamId::MaxAngleLow) {
            const ParameterValue *high = find(ParamId::MaxAngleHigh);
            if (!high)
                continue; // half an angle is no angle
            read.append(*high);
        }
        const QJsonObject fields = of(read);
        QJsonObject &into = info.layout == protocol::ParamLayout::Pid ? pid : params;
        for (auto it = fields.begin(); it != fields.end(); ++it)
            into.insert(it.key(), it.value());
    }
}

} // namespace lk::record
