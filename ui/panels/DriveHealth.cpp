#include "DriveHealth.h"

#include "Format.h"

#include <motor/SeriesLimits.h>

namespace lk::ui {

using F = bus::TelemetryField;

DriveHealth DriveHealth::of(const DriveRecord &d)
{
    DriveHealth h;
    const auto &v = d.latest;
    // The flags' meaning and the voltage's scale follow the generation (read_model).
    const bool known = d.generation().has_value();
    h.faults = known && d.has(F::ErrorState) && v.errorState != 0;
    h.hot = d.has(F::Temperature) && v.temperatureC >= kHotTemperatureC;
    if (known && d.has(F::Voltage) && d.series) {
        const motor::SeriesLimits &l = motor::seriesLimits(*d.series);
        h.lowVoltage = v.voltageV < l.minSupplyV;
        h.highVoltage = v.voltageV > l.maxSupplyV;
    }
    return h;
}

std::optional<QString> DriveHealth::supplyRangeText(const DriveRecord &d)
{
    if (!d.series)
        return std::nullopt;
    const motor::SeriesLimits &l = motor::seriesLimits(*d.series);
    return tr("%1: %2-%3 V")
        .arg(d.seriesText(),
             Format::number(l.minSupplyV, l.minSupplyV == int(l.minSupplyV) ? 0 : 1),
             Format::number(l.maxSupplyV, 0));
}

QStringList DriveHealth::problems(const DriveRecord &d) const
{
    QStringList out;
    const auto &v = d.latest;
    if (faults)
        out << tr("fault flags %1 (0x%2)")
                   .arg(Format::errorFlagsText(v.errorState, d.generation()))
                   .arg(v.errorState, 2, 16, QLatin1Char('0'));
    if (hot)
        out << tr("temperature %1 (hot from %2 °C)")
                   .arg(Format::withUnit(v.temperatureC, 0, QStringLiteral("\u00b0C")))
                   .arg(kHotTemperatureC);
    if (voltageOut()) {
        const int decimals = d.generation() == protocol::Generation::V2_35 ? 2 : 1;
        out << (lowVoltage ? tr("supply %1, below the series' range (%2)")
                           : tr("supply %1, above the series' range (%2)"))
                   .arg(Format::withUnit(v.voltageV, decimals, QStringLiteral("V")),
                        supplyRangeText(d).value_or(QString()));
    }
    return out;
}

} // namespace lk::ui
