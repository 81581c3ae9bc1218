#pragma once

#include "MotorRegistry.h"
#include "TelemetryBatcher.h"
#include "TelemetrySample.h"

#include <protocol/Command.h>
#include <protocol/Reply.h>

#include <optional>

namespace lk::bus {

/// What the bus learns from a drive's reply, whoever asked for it: the drive is seen (its
/// generation and series from a model reply, its generation from a command only one
/// generation has), whether it moves, and the telemetry sample it carries, batched. The
/// active path (BusWorker, our own requests) and the passive one (ListenMonitor, another
/// master's) both feed it, so an observed reply becomes the same sample a polled one does.
class ReplyIntake {
public:
    /// Who asked, as far as it matters to the decode.
    struct Asked {
        protocol::Command command = protocol::Command::ReadState2; ///< the request's command
        /// A scan's probe, sent before the drive's model told its layouts: no telemetry.
        bool scanProbe = false;
        quint64 pollCycle = 0; ///< TelemetrySample::cycle
        double pollCycleStart = 0;
    };

    ReplyIntake(MotorRegistry &motors, TelemetryBatcher &telemetry)
        : m_motors(motors), m_telemetry(telemetry)
    {
    }

    /// Takes `reply` (arrived at `time`, session seconds). Returns the sample it batched, if
    /// the reply carries telemetry; `motorsChanged` is set when the known drives changed.
    std::optional<TelemetrySample> take(const protocol::Reply &reply, double time,
                                        const Asked &asked, bool &motorsChanged);

private:
    MotorRegistry &m_motors;
    TelemetryBatcher &m_telemetry;
};

} // namespace lk::bus
