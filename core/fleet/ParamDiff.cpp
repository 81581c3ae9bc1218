#include "ParamDiff.h"

#include <algorithm>

namespace lk::fleet {

std::optional<qint64> ParamDiff::value(const DriveSnapshot &drive, const QString &key)
{
    const auto it = drive.values.constFind(key);
    if (it == drive.values.constEnd())
        return std::nullopt;
    return it->value;
}

QStringList ParamDiff::keys(const QVector<DriveSnapshot> &drives)
{
    QStringList out;
    for (protocol::Link l : {protocol::Link::Rs485, protocol::Link::Can}) {
        for (protocol::Generation g : {protocol::Generation::V2_3, protocol::Generation::V2_35}) {
            const bool present =
                std::any_of(drives.begin(), drives.end(), [g, l](const DriveSnapshot &d) {
                    return d.identified && d.identity.generation == g && d.identity.link == l;
                });
            for (const FleetParam &p : FleetCatalog::params(g, l)) {
                if (present && !out.contains(p.key))
                    out << p.key;
            }
        }
    }
    return out;
}

QVector<DiffRow> ParamDiff::rows(const DriveSnapshot &a, const DriveSnapshot &b)
{
    QStringList order;
    for (const DriveSnapshot *d : {&a, &b}) {
        if (!d->identified)
            continue;
        for (const FleetParam &p : FleetCatalog::params(d->identity.generation, d->identity.link)) {
            if (!order.contains(p.key))
                order << p.key;
        }
    }
    QVector<DiffRow> out;
    for (const QString &key : std::as_const(order))
        out << DiffRow{key, value(a, key), value(b, key)};
    return out;
}

const char *ParamDiff::stateName(DiffRow::State state)
{
    switch (state) {
    case DiffRow::State::Same:
        return "same";
    case DiffRow::State::Differs:
        return "differs";
    case DiffRow::State::Unknown:
        break;
    }
    return "unknown";
}

} // namespace lk::fleet
