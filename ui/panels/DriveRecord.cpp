#include "DriveRecord.h"

#include <QtCore/QLocale>

namespace lk::ui {

int DriveRecord::fieldIndex(bus::TelemetryField f)
{
    const auto bits = static_cast<quint16>(f);
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
    using F = bus::TelemetryField;
    if (s.has(F::Temperature))
        latest.temperatureC = s.temperatureC;
    if (s.has(F::IqA))
        latest.iqA = s.iqA;
    if (s.has(F::Power))
        latest.power = s.power;
    if (s.has(F::Speed))
        latest.speedDps = s.speedDps;
    if (s.has(F::Encoder))
        latest.encoder = s.encoder;
    if (s.has(F::Voltage))
        latest.voltageV = s.voltageV;
    if (s.has(F::ErrorState))
        latest.errorState = s.errorState;
    if (s.has(F::MultiTurn))
        latest.multiTurnDeg = s.multiTurnDeg;
    if (s.has(F::SingleTurn))
        latest.singleTurnDeg = s.singleTurnDeg;
    if (s.has(F::BusCurrent))
        latest.busCurrentA = s.busCurrentA;
    if (s.has(F::MotorOn))
        latest.motorOn = s.motorOn;
    if (s.has(F::PhaseCurrents)) {
        latest.iaA = s.iaA;
        latest.ibA = s.ibA;
        latest.icA = s.icA;
    }
    latest.id = s.id;
    latest.time = s.time;
    latest.source = s.source;
    latest.fields |= s.fields;
    for (int i = 0; i < kFieldCount; ++i) {
        if (s.fields.testFlag(static_cast<F>(1u << i)))
            updatedMs[static_cast<size_t>(i)] = nowMs;
    }
}

std::optional<double> DriveRecord::gearRatio() const
{
    if (!nameInfo.gearFromName)
        return std::nullopt;
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
