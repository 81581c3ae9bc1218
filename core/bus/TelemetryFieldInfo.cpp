#include "TelemetryFieldInfo.h"

#include <QtCore/QtGlobal>

namespace lk::bus {

namespace {
using F = TelemetryField;
using Q = Quantity;
using S = TelemetrySample;
} // namespace

const QVector<TelemetryFieldInfo> &TelemetryFieldInfo::all()
{
    // The order is the column order of every CSV file and JSON line (docs/CSV.md): keep it.
    // CSV decimals follow the resolution on the wire: 0.1 V (V2.3; V2.35 sends 0.01 V), 0.01 A
    // bus current, 0.01 deg, 33/2048 A (iq), 1/64 A (phases), whole degrees/s, counts and
    // degrees C. The readouts show V2.35's 0.01 V and hundredths of a degree per second.
    static const QVector<TelemetryFieldInfo> kRows{
        {F::Temperature, "temperature_c", "°C", Q::Temperature, 0, 0, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Temperature"), &S::temperatureC},
        {F::Voltage, "voltage_v", "V", Q::Voltage, 1, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Voltage"), &S::voltageV},
        {F::ErrorState, "error_state", "bit field", Q::State, 0, 0, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Error flags"), &S::errorState},
        {F::IqA, "iq_a", "A", Q::Current, 4, 4, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "iq"), &S::iqA},
        {F::Power, "power", "relative, -1000..1000", Q::Power, 0, 0, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Power"), &S::power},
        {F::Speed, "speed_dps", "°/s", Q::Speed, 0, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Speed"), &S::speedDps},
        {F::Encoder, "encoder", "counts", Q::Encoder, 0, 0, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Encoder"), &S::encoder},
        {F::MultiTurn, "multi_turn_deg", "°", Q::Angle, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Multi-turn angle"), &S::multiTurnDeg},
        {F::SingleTurn, "single_turn_deg", "°", Q::Angle, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Single-turn angle"), &S::singleTurnDeg},
        {F::PhaseCurrents, "ia_a", "A", Q::Current, 4, 4, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Phase A"), &S::iaA},
        {F::PhaseCurrents, "ib_a", "A", Q::Current, 4, 4, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Phase B"), &S::ibA},
        {F::PhaseCurrents, "ic_a", "A", Q::Current, 4, 4, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Phase C"), &S::icA},
        {F::BusCurrent, "bus_current_a", "A", Q::Current, 2, 2, true,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Bus current"), &S::busCurrentA},
        {F::MotorOn, "motor_on", "1 on, 0 off", Q::State, 0, 0, true,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Motor"), &S::motorOn},
        // Another master's commands (listen-only), at the resolution of their requests.
        {F::CommandedIq, "commanded_iq_a", "A", Q::Current, 4, 4, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded iq"), &S::commandedIqA},
        {F::CommandedPower, "commanded_power", "relative, -1000..1000", Q::Power, 0, 0, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded power"), &S::commandedPower},
        {F::CommandedSpeed, "commanded_speed_dps", "°/s", Q::Speed, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded speed"),
         &S::commandedSpeedDps},
        {F::CommandedAngle, "commanded_angle_deg", "°", Q::Angle, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded angle"),
         &S::commandedAngleDeg},
        {F::CommandedSingleTurn, "commanded_single_turn_deg", "°", Q::Angle, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded single-turn angle"),
         &S::commandedSingleTurnDeg},
        {F::CommandedDirection, "commanded_direction", "0 clockwise, 1 counter-clockwise", Q::State,
         0, 0, false, QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded direction"),
         &S::commandedDirection},
        {F::CommandedIncrement, "commanded_increment_deg", "°", Q::Angle, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded increment"),
         &S::commandedIncrementDeg},
        {F::CommandedMaxSpeed, "commanded_max_speed_dps", "°/s", Q::Speed, 2, 2, false,
         QT_TRANSLATE_NOOP("lk::bus::TelemetryFieldInfo", "Commanded speed limit"),
         &S::commandedMaxSpeedDps},
    };
    return kRows;
}

double TelemetryFieldInfo::value(const TelemetrySample &sample) const
{
    return std::visit([&sample](auto m) { return static_cast<double>(sample.*m); }, member);
}

void TelemetryFieldInfo::copy(TelemetrySample &into, const TelemetrySample &from) const
{
    std::visit([&](auto m) { into.*m = from.*m; }, member);
}

std::optional<int> TelemetryFieldInfo::indexOf(const QString &key)
{
    const QVector<TelemetryFieldInfo> &rows = all();
    for (int i = 0; i < rows.size(); ++i) {
        if (key == QLatin1String(rows.at(i).key))
            return i;
    }
    return std::nullopt;
}

QVector<int> TelemetryFieldInfo::of(TelemetryFields fields)
{
    QVector<int> out;
    const QVector<TelemetryFieldInfo> &rows = all();
    for (int i = 0; i < rows.size(); ++i) {
        if (fields.testFlag(rows.at(i).field))
            out.append(i);
    }
    return out;
}

} // namespace lk::bus
