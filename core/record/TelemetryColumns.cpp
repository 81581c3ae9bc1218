#include "TelemetryColumns.h"

#include <cmath>
#include <limits>

namespace lk::record {

using bus::TelemetryField;
using bus::TelemetrySample;

const QVector<TelemetryColumn> &TelemetryColumns::all()
{
    // Decimals follow the resolution on the wire: 0.1 V (V2.3; V2.35 sends 0.01 V), 0.01 A bus
    // current, 0.01 deg, 33/2048 A (iq), 1/64 A (phases), whole degrees/s, counts and degrees C.
    static const QVector<TelemetryColumn> kColumns{
        {"temperature_c", "°C", TelemetryField::Temperature, 0,
         [](const TelemetrySample &s) { return double(s.temperatureC); }},
        {"voltage_v", "V", TelemetryField::Voltage, 1,
         [](const TelemetrySample &s) { return s.voltageV; }},
        {"error_state", "bit field", TelemetryField::ErrorState, 0,
         [](const TelemetrySample &s) { return double(s.errorState); }},
        {"iq_a", "A", TelemetryField::IqA, 4, [](const TelemetrySample &s) { return s.iqA; }},
        {"power", "relative, -1000..1000", TelemetryField::Power, 0,
         [](const TelemetrySample &s) { return double(s.power); }},
        {"speed_dps", "°/s", TelemetryField::Speed, 0,
         [](const TelemetrySample &s) { return s.speedDps; }},
        {"encoder", "counts", TelemetryField::Encoder, 0,
         [](const TelemetrySample &s) { return double(s.encoder); }},
        {"multi_turn_deg", "°", TelemetryField::MultiTurn, 2,
         [](const TelemetrySample &s) { return s.multiTurnDeg; }},
        {"single_turn_deg", "°", TelemetryField::SingleTurn, 2,
         [](const TelemetrySample &s) { return s.singleTurnDeg; }},
        {"ia_a", "A", TelemetryField::PhaseCurrents, 4,
         [](const TelemetrySample &s) { return s.iaA; }},
        {"ib_a", "A", TelemetryField::PhaseCurrents, 4,
         [](const TelemetrySample &s) { return s.ibA; }},
        {"ic_a", "A", TelemetryField::PhaseCurrents, 4,
         [](const TelemetrySample &s) { return s.icA; }},
        {"bus_current_a", "A", TelemetryField::BusCurrent, 2,
         [](const TelemetrySample &s) { return s.busCurrentA; }},
        {"motor_on", "1 on, 0 off", TelemetryField::MotorOn, 0,
         [](const TelemetrySample &s) { return s.motorOn ? 1.0 : 0.0; }},
    };
    return kColumns;
}

std::optional<int> TelemetryColumns::indexOf(const QString &key)
{
    const QVector<TelemetryColumn> &columns = all();
    for (int i = 0; i < columns.size(); ++i) {
        if (key == QLatin1String(columns.at(i).key)) {
            return i;
        }
    }
    return std::nullopt;
}

QVector<int> TelemetryColumns::of(bus::TelemetryFields fields)
{
    QVector<int> out;
    const QVector<TelemetryColumn> &columns = all();
    for (int i = 0; i < columns.size(); ++i) {
        if (fields.testFlag(columns.at(i).field)) {
            out.append(i);
        }
    }
    return out;
}

QVector<double> TelemetryColumns::empty()
{
    return QVector<double>(all().size(), std::numeric_limits<double>::quiet_NaN());
}

QVector<double> TelemetryColumns::values(const TelemetrySample &sample)
{
    QVector<double> out = empty();
    const QVector<TelemetryColumn> &columns = all();
    for (int i = 0; i < columns.size(); ++i) {
        if (sample.has(columns.at(i).field)) {
            out[i] = columns.at(i).read(sample);
        }
    }
    return out;
}

void TelemetryColumns::merge(QVector<double> &into, const QVector<double> &from)
{
    Q_ASSERT(into.size() == from.size());
    for (qsizetype i = 0; i < from.size(); ++i) {
        if (!std::isnan(from.at(i))) {
            into[i] = from.at(i);
        }
    }
}

} // namespace lk::record
