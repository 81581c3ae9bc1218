#include "DriveRecord.h"

#include <QtCore/QLocale>

namespace lk::ui {

int DriveRecord::fieldIndex(bus::TelemetryField f)
{
    const auto bits = static_cast<quint32>(f);
    for (int i = 0; i < kFieldCount; ++i) {
        if (bits == (1u << i))
            return i;
    }
    return -1;
}

qint64 DriveRecord::updatedAt(bus::TelemetryField f) const
{
    const int i = fieldIndex(f);
    return i < 0 ? 0 : updatedMs[static_cast<size_t>(i)];
}

bool DriveRecord::isStale(bus::TelemetryField f, qint64 nowMs) const
{
    if (!has(f))
        return true;
    return nowMs - updatedAt(f) > kStaleMs;
}

void DriveRecord::apply(const bus::TelemetrySample &s, qint64 nowMs)
{
    latest.merge(s);
    for (int i = 0; i < kFieldCount; ++i) {
        if (s.fields.testFlag(static_cast<bus::TelemetryField>(1u << i)))
            updatedMs[static_cast<size_t>(i)] = nowMs;
    }
}

std::optional<double> DriveRecord::gearRatio() const
{
    if (!nameInfo.gearFromName)
        return chosenGearRatio;
    return nameInfo.gearRatio;
}

QString DriveRecord::seriesText() const
{
    return series ? protocol::seriesName(*series) : QStringLiteral("?");
}

QString DriveRecord::modelText() const
{
    if (!model)
        return {};
    if (model->driverName.isEmpty())
        return model->motorName;
    return QStringLiteral("%1 (%2)").arg(model->motorName, model->driverName);
}

QString DriveRecord::firmwareText() const
{
    return model ? QLocale().toString(model->firmwareVersion(), 'f',
                                      model->generation == protocol::Generation::V2_3 ? 1 : 2)
                 : QString();
}

QString DriveRecord::hardwareText() const
{
    return model ? QLocale().toString(model->hardwareVersion(), 'f',
                                      model->generation == protocol::Generation::V2_3 ? 1 : 2)
                 : QString();
}

} // namespace lk::ui
