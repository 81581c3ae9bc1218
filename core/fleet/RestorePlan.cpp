#include "RestorePlan.h"

namespace lk::fleet {

namespace {

QString seriesText(const std::optional<protocol::Series> &s)
{
    return s ? protocol::seriesName(*s) : QStringLiteral("unknown");
}

/// "CAN V2.36", "RS485 v2.35": a generation means little without its link.
QString dialectText(const DriveIdentity &who)
{
    return protocol::dialectName(
        {who.series.value_or(protocol::Series::MF), who.generation, who.link});
}

/// ", declared" where the identity is the user's word (CAN), not a model read.
QString how(const DriveIdentity &who)
{
    return who.declared ? QStringLiteral(" (declared)") : QString();
}

/// Link, generation and series must be the source's (on CAN the target's are declared).
std::optional<Refusal> identityRefusal(const DriveIdentity &from, const DriveIdentity &to)
{
    if (from.link != to.link)
        return Refusal{QStringLiteral("link"),
                       QStringLiteral("link differs: the source is on %1, drive %2 is on %3")
                           .arg(protocol::linkName(from.link))
                           .arg(to.id)
                           .arg(protocol::linkName(to.link))};
    if (from.generation != to.generation)
        return Refusal{QStringLiteral("generation"),
                       QStringLiteral("generation differs: the source is %1%2, drive %3 is %4%5")
                           .arg(dialectText(from), how(from))
                           .arg(to.id)
                           .arg(dialectText(to), how(to))};
    if (!from.series || !to.series || *from.series != *to.series)
        return Refusal{QStringLiteral("series"),
                       QStringLiteral("series differs: the source is %1%2, drive %3 is %4%5")
                           .arg(seriesText(from.series), how(from))
                           .arg(to.id)
                           .arg(seriesText(to.series), how(to))};
    return std::nullopt;
}

std::optional<Refusal> refusalOf(const DriveSnapshot &source, const DriveSnapshot &target)
{
    if (!source.complete() || !source.failure.isEmpty())
        return Refusal{
            QStringLiteral("source"),
            QStringLiteral("the source (drive %1) was not read completely: %2")
                .arg(source.id())
                .arg(source.failure.isEmpty() ? QStringLiteral("values missing") : source.failure)};
    const DriveIdentity &from = source.identity;
    const DriveIdentity &to = target.identity;
    // A target whose identity is known but not the source's is refused for that first: a
    // declared generation that is wrong may also be why its read failed.
    if (target.identified) {
        if (std::optional<Refusal> r = identityRefusal(from, to))
            return r;
    }
    if (!target.complete() || !target.failure.isEmpty())
        return Refusal{
            QStringLiteral("read"),
            QStringLiteral("drive %1 could not be read first, so nothing is written "
                           "to it: %2")
                .arg(target.id())
                .arg(target.failure.isEmpty() ? QStringLiteral("values missing") : target.failure)};
    for (const FleetParam &p : FleetCatalog::params(to.generation, to.link)) {
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
    for (const FleetParam &p :
         FleetCatalog::params(target.identity.generation, target.identity.link)) {
        const qint64 from = target.values.value(p.key).value;
        const qint64 to = source.values.value(p.key).value;
        if (p.restorable && from != to)
            plan.changes << ParamChange{p.key, from, to};
    }
    return plan;
}

} // namespace lk::fleet
