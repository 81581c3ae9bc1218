#include "ParamWrite.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"
#include "RequestText.h"
#include "Subcommand.h"

#include <record/ParameterFields.h>

namespace lk::lkctl {

using protocol::ParameterValue;
using protocol::ParamTable;

namespace {

QString valueNames(const DriveParam &p)
{
    QStringList names;
    for (const protocol::FieldSpec &f : p.fields)
        names << f.name.toUpper();
    return names.join(QLatin1Char(' '));
}

} // namespace

QString ParamWrite::Plan::command() const
{
    return rom ? QStringLiteral("write_param_rom") : QStringLiteral("write_param_ram");
}

std::optional<ParamWrite::Plan> ParamWrite::plan(const QStringList &pos, bool rom, bool json,
                                                 QString *error)
{
    if (pos.size() < 3) {
        *error = QStringLiteral("param takes NAME and its values; NAME is one of %1")
                     .arg(DriveParams::names());
        return std::nullopt;
    }
    const std::optional<DriveParam> param = DriveParams::find(pos.at(2));
    if (!param) {
        *error = QStringLiteral("no parameter '%1'; NAME is one of %2")
                     .arg(pos.at(2), DriveParams::names());
        return std::nullopt;
    }
    const QStringList values = pos.mid(3);
    if (values.size() != param->fields.size()) {
        *error = QStringLiteral("%1 takes %2 (got %3 value%4)")
                     .arg(param->name, valueNames(*param))
                     .arg(values.size())
                     .arg(values.size() == 1 ? QString() : QStringLiteral("s"));
        return std::nullopt;
    }
    Plan plan;
    plan.id = pos.at(0).toInt(); // checked by the caller
    plan.param = *param;
    plan.rom = rom;
    plan.json = json;
    for (protocol::ParamId id : param->ids) {
        FieldValues fields;
        fields.insert(QStringLiteral("id"), pos.at(0));
        fields.insert(QStringLiteral("param"), ParamTable::name(id));
        for (qsizetype i = 0; i < values.size(); ++i)
            fields.insert(param->fields.at(i).name, values.at(i));
        // Every range is checked here, before anything is sent (a pair is sent whole or not).
        const FieldBuildResult built = RequestText::build(plan.command(), fields);
        if (!built.ok()) {
            *error = built.message;
            return std::nullopt;
        }
        plan.requests.append(*built.request);
        plan.written.append(std::get<ParameterValue>(built.request->payload));
    }
    return plan;
}

int ParamWrite::run(LiveBus &bus, const Plan &plan)
{
    bool lost = false;
    bool failed = false;
    for (const protocol::Request &request : plan.requests) {
        // Sent once: the bus never repeats a ROM write; a lost reply is answered by the
        // read-back below, not by sending again.
        const bus::RequestResult w = bus.request(request);
        if (!w.ok()) {
            bus.reportFailure(w);
            if (w.status != bus::RequestStatus::Timeout && w.status != bus::RequestStatus::Error)
                return kExitFailure;
            lost = true;
            break;
        }
        const auto *result =
            w.reply ? std::get_if<protocol::ParamWriteResult>(&w.reply->payload) : nullptr;
        const auto sentId = std::get<ParameterValue>(request.payload).paramId;
        if (!result || !result->succeeded() || result->paramId != sentId) {
            bus.error(QStringLiteral("drive %1 reported that writing %2 failed (%3 of %4 answered "
                                     "flag %5: 1 = failure)%6")
                          .arg(plan.id)
                          .arg(plan.param.name, plan.command(),
                               ParamTable::name(protocol::ParamId(sentId)))
                          .arg(result ? result->flag : -1)
                          .arg(plan.requests.size() > 1 ? QStringLiteral("; the rest of the pair "
                                                                         "was not sent")
                                                        : QString()));
            failed = true;
            break;
        }
    }
    if (lost)
        bus.error(QStringLiteral("reading back what drive %1 holds now (if it matches, the write "
                                 "took effect and only its reply was lost):")
                      .arg(plan.id));
    const int status = readBack(bus, plan);
    return failed ? kExitFailure : status;
}

int ParamWrite::readBack(LiveBus &bus, const Plan &plan)
{
    const std::optional<QList<ParameterValue>> values = DriveParams::read(bus, plan.id, plan.param);
    if (!values) {
        bus.error(QStringLiteral("the read-back of %1 failed").arg(plan.param.name));
        return kExitFailure;
    }
    const QJsonObject written = record::ParameterFields::of(plan.written);
    const QJsonObject holds = record::ParameterFields::of(*values);
    const bool same = written == holds;
    Console &console = bus.console();
    if (plan.json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), plan.command())
            .integer(QStringLiteral("id"), plan.id)
            .text(QStringLiteral("param"), plan.param.name)
            .fields(QStringLiteral("written"), written)
            .fields(QStringLiteral("holds"), holds)
            .boolean(QStringLiteral("match"), same);
        console.out(o.toJson() + '\n');
    } else {
        console.outLine(QStringLiteral("Drive %1 now holds (%2, read back with read_param):")
                            .arg(plan.id)
                            .arg(plan.rom ? QStringLiteral("in RAM; write_param_rom wrote ROM too")
                                          : QStringLiteral("RAM")));
        for (const QString &line : ReplyText::lines(holds, QStringLiteral("  ")))
            console.outLine(line);
    }
    if (same)
        return kExitOk;
    bus.error(QStringLiteral("read-back mismatch on drive %1: wrote %2 (%3) but the drive holds "
                             "%4.")
                  .arg(plan.id)
                  .arg(plan.param.name, ReplyText::oneLine(written), ReplyText::oneLine(holds)));
    return kExitMismatch;
}

} // namespace lk::lkctl
