#pragma once

#include "DriveRecord.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace lk::ui {

/// What is wrong with a drive's latest values: fault flags set, the temperature at or above
/// the warning threshold, the supply outside its series' range (motor::SeriesLimits). The
/// dashboard and the overview colour these values red; DriveFaultWatch raises a banner entry
/// and a log line when one appears (docs/SUPERVISION.md). Flags and supply are judged once the
/// drive's generation is known (its model read), as their decoding depends on it.
struct DriveHealth {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::DriveHealth)
public:
    /// The temperature from which a drive is shown hot: 15 °C below the 85 °C at which LK
    /// drives' (and lksim's) over-temperature protection switches the motor off, so that
    /// there is time to act; drives under load run at 40-60 °C.
    static constexpr int kHotTemperatureC = 70;

    bool faults = false;      ///< error flags set
    bool hot = false;         ///< temperature >= kHotTemperatureC
    bool lowVoltage = false;  ///< below the series' minimum supply
    bool highVoltage = false; ///< above the series' maximum supply

    static DriveHealth of(const DriveRecord &drive);
    bool voltageOut() const { return lowVoltage || highVoltage; }
    bool ok() const { return !faults && !hot && !voltageOut(); }
    bool operator==(const DriveHealth &o) const
    {
        return faults == o.faults && hot == o.hot && lowVoltage == o.lowVoltage &&
               highVoltage == o.highVoltage;
    }

    /// The series' supply range of a drive ("12-36 V"); nullopt while its series is unknown.
    static std::optional<QString> supplyRangeText(const DriveRecord &drive);
    /// Each problem as a translated clause with the value: "over-temperature (0x08)",
    /// "84 °C (hot from 70 °C)", "supply 9.8 V (MF: 12-36 V)".
    QStringList problems(const DriveRecord &drive) const;
};

} // namespace lk::ui
