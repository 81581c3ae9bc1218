#include "RestorePlan.h"

namespace lk::fleet {

namespace {

QString seriesText(const std::optional<protocol::Series> &s)
{
    return s ? protocol::seriesName(*s) : QStringLiteral("unknown");
}

std::optional<Refusal> refusalOf(const DriveSnapshot &source, const DriveSnapshot &target)
{
    if (!source.complete() || !source.failure.isEmpty())
        return Refusal{
            QStringLiteral("source"),
            QStringLiteral("the source (drive %1) was not read completely: %2")
                .arg(source.id())
                .arg(source.failure.isEmpty() ? QStringLiteral("values missing") : source.failure)};
    if (!target.complete() || !target.failure.isEmpty())
        return Refusal{
            QStringLiteral("read"),
            QStringLiteral("drive %1 could not be read first, so nothing is written "
                           "to it: %2")
                .arg(target.id())
                .arg(target.failure.isEmpty() ? QStringLiteral("values missing") : target.failure)};
    const DriveIdentity &from = source.identity;
    const DriveIdentity &to = target.identity;
    if (from.generation != to.generation)
        return Refusal{QStringLiteral("generation"),
                       QStringLiteral("generation differs: the source is %1, drive %2 is %3")
                           .arg(protocol::generationName(from.generation))
                           .arg(to.id)
                           .arg(protocol::generationName(to.generation))};
    if (!from.series || !to.series || *from.series != *to.series)
        return Refusal{QStringLiteral("series"),
                       QStringLiteral("series differs: the source is %1, drive %2 is %3")
                           .arg(seriesText(from.series))
                           .arg(to.id)
                           .arg(seriesText(to.series))};
    for (const FleetParam &p : FleetCatalog::params(to.generation)) {
        const qint64 v = source.values.value(p.key).value;
        if (p.restorable && (v < p.min || v > p.max))
            return Refusal{p.key, QStringLiteral("%1 is %2, outside drive %3's range %4..%5")
                                      .arg(p.key)
                                      .arg(v)
                                      .arg(to.id)
                                      .arg(p.min)
                                      .arg(p.max)};
    }
    return std::nullopt;
}

} // namespace

QStringList RestorePlan::changedKeys() const
{
    QStringList keys;
    for (const ParamChange &c : changes)
        keys << c.key;
    return keys;
}

RestorePlan RestorePlan::make(const DriveSnapshot &source, const DriveSnapshot &target)
{
    RestorePlan plan;
    plan.source = source;
    plan.target = target;
    plan.refusal = refusalOf(source, target);
    if (plan.refusal)
        return plan;
    for (const FleetParam &p : FleetCatalog::params(target.identity.generation)) {
        const qint64 from = target.values.value(p.key).value;
        const qint64 to = source.values.value(p.key).value;
        if (p.restorable && from != to)
            plan.changes << ParamChange{p.key, from, to};
    }
    return plan;
}

} // namespace lk::fleet
