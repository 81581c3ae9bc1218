#pragma once

#include "protocol/Series.h"

#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace lk::sim {

/// A protection fault a simulated drive raises by itself: the errorState bit it sets, when its
/// cause appears and when the cause goes, in seconds after the drive powered up. While the
/// cause lasts the flag cannot be cleared (0x9B); once it has gone, 0x9B clears it.
///
/// Written NAME[@START[-END]], times in seconds with an optional "s" ("over_temperature@5s",
/// "stall@2-4.5s", "low_voltage": from power-up, for good). NAME is one of the error flags of
/// the drive's generation (protocol::ErrorFlags): V2.3 low_voltage and over_temperature; V2.35
/// low_voltage, over_voltage, driver_over_temperature, motor_over_temperature (also
/// over_temperature), over_current, short_circuit, stall, input_timeout.
struct SimFault {
    int bit = 0; ///< 0..7 of errorState
    double startS = 0;
    std::optional<double> endS; ///< nullopt: the cause stays until the drive is power-cycled

    bool activeAt(double uptimeS) const { return uptimeS >= startS && (!endS || uptimeS < *endS); }
    quint8 mask() const { return static_cast<quint8>(1u << bit); }

    /// Parses one fault for a drive of `generation`; nullopt with one sentence in `error`.
    static std::optional<SimFault> parse(const QString &text, protocol::Generation generation,
                                         QString *error = nullptr);
    /// Back to text, in the generation's flag name.
    QString toString(protocol::Generation generation) const;
    /// The fault names a generation accepts, for help and error texts.
    static QStringList names(protocol::Generation generation);

    bool operator==(const SimFault &o) const
    {
        return bit == o.bit && startS == o.startS && endS == o.endS;
    }
};

} // namespace lk::sim
