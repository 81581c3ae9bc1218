#pragma once

#include <fleet/DriveSnapshot.h>

namespace lk::fleettest {

/// A completely read drive of `generation` whose every value is `base` plus its row number. On
/// CAN its identity is declared (no names or versions, as CAN has no model read).
inline fleet::DriveSnapshot snapshot(int id, protocol::Generation generation,
                                     protocol::Series series = protocol::Series::MF,
                                     qint64 base = 10, protocol::Link link = protocol::Link::Rs485)
{
    fleet::DriveSnapshot d;
    d.identity.id = id;
    d.identity.link = link;
    if (link == protocol::Link::Can) {
        d.identity.declared = true;
        d.identity.series = series;
        d.identity.generation = generation;
        d.identified = true;
        d.readAt = QDateTime(QDate(2026, 11, 27), QTime(10, 0), Qt::UTC);
        qint64 n = base;
        for (const fleet::FleetParam &p : fleet::FleetCatalog::params(generation, link))
            d.values.insert(p.key, fleet::ReadValue{n++, d.readAt.addMSecs(n)});
        return d;
    }
    d.identity.driverName = QStringLiteral("LK-DRV");
    d.identity.motorName = protocol::seriesName(series) + QStringLiteral("4015");
    d.identity.series = series;
    d.identity.generation = generation;
    d.identity.hardwareRaw = 10;
    d.identity.firmwareRaw = generation == protocol::Generation::V2_3 ? 23 : 235;
    if (generation == protocol::Generation::V2_35)
        d.identity.uniqueId = QByteArray::fromHex("353735303032731878034142");
    d.identified = true;
    d.readAt = QDateTime(QDate(2026, 11, 27), QTime(10, 0), Qt::UTC);
    qint64 n = base;
    for (const fleet::FleetParam &p : fleet::FleetCatalog::params(generation))
        d.values.insert(p.key, fleet::ReadValue{n++, d.readAt.addMSecs(n)});
    return d;
}

} // namespace lk::fleettest
