#include "ControlParamWrite.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"
#include "Subcommand.h"

#include <protocol/FieldJson.h>
#include <protocol/ProtocolFields.h>
#include <protocol/RequestBuilder.h>

namespace lk::lkctl {

using protocol::ControlParameter;
using protocol::ControlParamId;
using protocol::ControlParamInfo;
using protocol::ControlParamLayout;
using protocol::ControlParamTable;

namespace {

const ControlParamId kLoops[] = {ControlParamId::AnglePid, ControlParamId::SpeedPid,
                                 ControlParamId::CurrentPid};

/// The name `write ID param` takes: a loop keeps the table's name (angle_pid), a value is
/// named by its field, as `read ID params` shows it (max_speed_dps, current_ramp_raw).
QString nameOf(const ControlParamInfo &info)
{
    return info.layout == ControlParamLayout::Pid
               ? QString::fromLatin1(info.name)
               : protocol::ProtocolFields::ofControlParam(info.id).constFirst().name;
}

/// The value fields of a control parameter, without the head that says which one it is.
QJsonObject valueFields(int id, const ControlParameter &value)
{
    const QJsonObject all = protocol::FieldJson::requestFields(
        protocol::Request{protocol::Command::WriteControlParam, quint8(id), value});
    QJsonObject out;
    for (auto it = all.begin(); it != all.end(); ++it) {
        if (!it.key().startsWith(QLatin1String("control_param")) && it.key() != QLatin1String("id"))
            out.insert(it.key(), it.value());
    }
    return out;
}

QJsonObject valueFields(int id, const QList<ControlParameter> &values)
{
    QJsonObject out;
    for (const ControlParameter &v : values) {
        const QJsonObject one = valueFields(id, v);
        for (auto it = one.begin(); it != one.end(); ++it)
            out.insert(it.key(), it.value());
    }
    return out;
}

std::optional<ControlParameter> built(const protocol::BuildResult &b, QString *error)
{
    if (!b.ok()) {
        *error = b.error.message();
        return std::nullopt;
    }
    return std::get<ControlParameter>(b.request->payload);
}

} // namespace

QString ControlParamWrite::names()
{
    QStringList n;
    for (const ControlParamInfo &info : ControlParamTable::all())
        n << nameOf(info);
    return n.join(QStringLiteral(", "));
}

QString ControlParamWrite::romRefusal(int id)
{
    return QStringLiteral("drive %1 speaks CAN V2.36: its gains and limits are control "
                          "parameters (0xC1), which are RAM only: it has no ROM write; nothing "
                          "was sent. Use --ram (the values last until power-off).")
        .arg(id);
}

std::optional<ControlParamWrite::Plan> ControlParamWrite::pidPlan(int id, const QStringList &gains,
                                                                  bool json, QString *error)
{
    static const char *const kNames[] = {"angle_kp", "angle_ki", "speed_kp",
                                         "speed_ki", "iq_kp",    "iq_ki"};
    Plan plan;
    plan.id = id;
    plan.json = json;
    for (int i = 0; i < 6; ++i) {
        bool ok = false;
        const qint64 v = gains.value(i).trimmed().toLongLong(&ok);
        if (!ok || v < 0 || v > 65535) {
            *error = QStringLiteral("%1 must be in 0..65535 on CAN V2.36 (got '%2')")
                         .arg(QLatin1String(kNames[i]), gains.value(i));
            return std::nullopt;
        }
        plan.gains[size_t(i)] = quint16(v);
    }
    for (ControlParamId loop : kLoops)
        plan.ids << loop;
    return plan;
}

std::optional<ControlParamWrite::Plan> ControlParamWrite::paramPlan(const QStringList &pos,
                                                                    bool json, QString *error)
{
    const ControlParamInfo *info = nullptr;
    for (const ControlParamInfo &each : ControlParamTable::all()) {
        if (pos.size() >= 3 && nameOf(each) == pos.at(2))
            info = &each;
    }
    if (!info) {
        *error = QStringLiteral("no control parameter '%1' on CAN V2.36; NAME is one of %2")
                     .arg(pos.value(2), names());
        return std::nullopt;
    }
    const QList<protocol::FieldSpec> fields = protocol::ProtocolFields::ofControlParam(info->id);
    const QStringList values = pos.mid(3);
    if (values.size() != fields.size()) {
        QStringList wanted;
        for (const protocol::FieldSpec &f : fields)
            wanted << f.name.toUpper();
        *error = QStringLiteral("%1 takes %2 (got %3)")
                     .arg(nameOf(*info), wanted.join(QLatin1Char(' ')))
                     .arg(values.size());
        return std::nullopt;
    }
    QList<double> numbers;
    for (qsizetype i = 0; i < values.size(); ++i) {
        bool ok = false;
        const double v = fields.at(i).kind == protocol::FieldKind::Integer
                             ? double(values.at(i).trimmed().toLongLong(&ok))
                             : values.at(i).trimmed().toDouble(&ok);
        if (!ok) {
            *error = QStringLiteral("%1 must be in %2 (got '%3')")
                         .arg(fields.at(i).name, fields.at(i).range, values.at(i));
            return std::nullopt;
        }
        numbers << v;
    }
    Plan plan;
    plan.id = pos.at(0).toInt(); // checked by the caller
    plan.json = json;
    plan.param = nameOf(*info);
    plan.ids << info->id;
    // Every range is checked here, before anything is sent.
    const std::optional<ControlParameter> value =
        built(info->layout == ControlParamLayout::Pid
                  ? protocol::build::writeControlParamPid(plan.id, info->id, qint64(numbers[0]),
                                                          qint64(numbers[1]), qint64(numbers[2]))
                  : protocol::build::writeControlParam(plan.id, info->id, numbers[0]),
              error);
    if (!value)
        return std::nullopt;
    plan.values << *value;
    return plan;
}

std::optional<ControlParameter> ControlParamWrite::read(LiveBus &bus, int id, ControlParamId param)
{
    const protocol::BuildResult b = protocol::build::readControlParam(id, param);
    const bus::RequestResult r = b.ok() ? bus.request(*b.request) : bus::RequestResult{};
    const auto *v = r.reply ? std::get_if<ControlParameter>(&r.reply->payload) : nullptr;
    if (!b.ok() || !r.ok() || !v || v->id() != param) {
        if (!b.ok())
            bus.error(b.error.message());
        else if (!r.ok())
            bus.reportFailure(r);
        else
            bus.error(QStringLiteral("drive %1 answered read_control_param %2 with another "
                                     "parameter")
                          .arg(id)
                          .arg(ControlParamTable::name(param)));
        return std::nullopt;
    }
    return *v;
}

int ControlParamWrite::run(LiveBus &bus, Plan plan)
{
    if (plan.isPid()) {
        // Six gains name Kp and Ki of each loop; the drive keeps Kd beside them in the same
        // parameter. Kd is read and written back as it is: never a value that was not read.
        for (int l = 0; l < 3; ++l) {
            const std::optional<ControlParameter> now = read(bus, plan.id, kLoops[l]);
            if (!now) {
                bus.error(QStringLiteral("drive %1's Kd could not be read, so no gain was "
                                         "written")
                              .arg(plan.id));
                return kExitFailure;
            }
            plan.values << ControlParameter::ofPid(kLoops[l], plan.gains[size_t(2 * l)],
                                                   plan.gains[size_t(2 * l + 1)], now->pid()[2]);
        }
    }
    bool failed = false;
    for (const ControlParameter &value : std::as_const(plan.values)) {
        const bus::RequestResult w =
            bus.request(*protocol::build::writeControlParam(plan.id, value).request);
        if (w.ok())
            continue;
        bus.reportFailure(w);
        if (w.status != bus::RequestStatus::Timeout && w.status != bus::RequestStatus::Error)
            return kExitFailure;
        // The reply may be what was lost: what the drive holds now answers whether it acted.
        bus.error(QStringLiteral("reading back what drive %1 holds now (if it matches, the write "
                                 "took effect and only its reply was lost); the rest was not "
                                 "sent:")
                      .arg(plan.id));
        failed = true;
        break;
    }
    const int status = readBack(bus, plan);
    return failed && status == kExitOk ? kExitFailure : status;
}

int ControlParamWrite::readBack(LiveBus &bus, const Plan &plan)
{
    QList<ControlParameter> holds;
    for (ControlParamId param : plan.ids) {
        const std::optional<ControlParameter> v = read(bus, plan.id, param);
        if (!v) {
            bus.error(QStringLiteral("the read-back of drive %1 failed").arg(plan.id));
            return kExitFailure;
        }
        holds << *v;
    }
    const QJsonObject written = valueFields(plan.id, plan.values);
    const QJsonObject held = valueFields(plan.id, holds);
    const bool same = written == held;
    Console &console = bus.console();
    if (plan.json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), QStringLiteral("write_control_param"))
            .integer(QStringLiteral("id"), plan.id);
        if (!plan.isPid())
            o.text(QStringLiteral("param"), plan.param);
        o.fields(QStringLiteral("written"), written)
            .fields(QStringLiteral("holds"), held)
            .boolean(QStringLiteral("ram_only"), true)
            .boolean(QStringLiteral("match"), same);
        console.out(o.toJson() + '\n');
    } else {
        console.outLine(
            QStringLiteral("Drive %1 now holds (RAM only: CAN V2.36 has no ROM write, "
                           "the values are lost at power-off; read back with "
                           "read_control_param%2):")
                .arg(plan.id)
                .arg(plan.isPid() ? QStringLiteral("; each Kd written back as read") : QString()));
        for (const QString &line : ReplyText::lines(held, QStringLiteral("  ")))
            console.outLine(line);
    }
    if (same)
        return kExitOk;
    bus.error(QStringLiteral("read-back mismatch on drive %1: wrote %2 but the drive holds %3.")
                  .arg(plan.id)
                  .arg(ReplyText::oneLine(written), ReplyText::oneLine(held)));
    return kExitMismatch;
}

} // namespace lk::lkctl
