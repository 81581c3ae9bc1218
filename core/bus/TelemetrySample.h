#pragma once

#include <protocol/Reply.h>
#include <protocol/Request.h>

#include <QtCore/QFlags>
#include <QtCore/QMetaType>
#include <QtCore/QObject>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {
// TelemetryField's keys are enumerable: a test walks them against the table.
Q_NAMESPACE
/// Which fields of a TelemetrySample carry a value. Each field has its rows in
/// TelemetryFieldInfo::all() (key, unit, label, ...): a new field takes the next bit, raises
/// kTelemetryFieldCount and adds its row there, and its decoder fills it in TelemetrySample.cpp.
enum class TelemetryField : quint32 {
    Temperature = 0x0001,
    IqA = 0x0002,   ///< MF/MG/MH torque current
    Power = 0x0004, ///< MS: relative power -1000..1000 instead of iq
    Speed = 0x0008,
    Encoder = 0x0010,
    Voltage = 0x0020,
    ErrorState = 0x0040,
    MultiTurn = 0x0080,
    PhaseCurrents = 0x0100,
    SingleTurn = 0x0200,
    BusCurrent = 0x0400, ///< V2.35 0x9A/0x9B only
    MotorOn = 0x0800,    ///< V2.35 0x9A/0x9B only: the motor state byte (on/off)
    // What another master commanded, from its requests (a listen-only session): beside the
    // drive's replies, commanded against actual.
    CommandedIq = 0x1000,          ///< 0xA1's iq, at the drive's scale (only when that is known)
    CommandedPower = 0x2000,       ///< 0xA0's open-loop power (MS)
    CommandedSpeed = 0x4000,       ///< 0xA2's speed
    CommandedAngle = 0x8000,       ///< 0xA3/0xA4's multi-turn target
    CommandedSingleTurn = 0x10000, ///< 0xA5/0xA6's single-turn target
    CommandedDirection = 0x20000,  ///< 0xA5/0xA6's way round: 0 clockwise, 1 counter-clockwise
    CommandedIncrement = 0x40000,  ///< 0xA7/0xA8's increment (the target is relative to where
                                   ///< the drive is, which the listener does not know exactly)
    CommandedMaxSpeed = 0x80000,   ///< 0xA4/0xA6/0xA8's speed limit of the move
};
Q_ENUM_NS(TelemetryField)
/// The bits TelemetryField uses: 1 << 0 .. 1 << (kTelemetryFieldCount - 1).
inline constexpr int kTelemetryFieldCount = 20;
Q_DECLARE_FLAGS(TelemetryFields, TelemetryField)
Q_DECLARE_OPERATORS_FOR_FLAGS(TelemetryFields)

/// One reply's worth of telemetry from one drive, in physical units, with a host timestamp.
/// Only the fields named in `fields` are meaningful.
struct TelemetrySample {
    int id = 0;
    double time = 0; ///< seconds since the session started (steady clock, host side)
    protocol::Command source = protocol::Command::ReadState2; ///< the reply it came from
    /// The poll round it answers (PollScheduler::cycle()), 0 when it answers no poll (an
    /// operator's read, a command's reply). Samples of one round share `cycle`/`cycleTime`.
    quint64 cycle = 0;
    double cycleTime = 0; ///< when that round began, same clock as `time`
    TelemetryFields fields;
    int temperatureC = 0;
    double iqA = 0;
    int power = 0;
    double speedDps = 0;
    int encoder = 0;
    double voltageV = 0;
    int errorState = 0;
    double multiTurnDeg = 0; ///< rotor degrees
    double singleTurnDeg = 0;
    double iaA = 0, ibA = 0, icA = 0;
    double busCurrentA = 0;
    bool motorOn = false;
    double commandedIqA = 0;
    int commandedPower = 0;
    double commandedSpeedDps = 0;
    double commandedAngleDeg = 0;      ///< rotor degrees, as multiTurnDeg
    double commandedSingleTurnDeg = 0; ///< as singleTurnDeg
    int commandedDirection = 0;        ///< the wire's byte: 0 clockwise, 1 counter-clockwise
    double commandedIncrementDeg = 0;  ///< rotor degrees, signed
    double commandedMaxSpeedDps = 0;
    /// A 0x90 reply in full: its raw position and offset are no telemetry columns (only
    /// `encoder` is), but the Encoder view shows them from the polls it adds.
    std::optional<protocol::EncoderReading> encoderReading;
    bool has(TelemetryField f) const { return fields.testFlag(f); }
    /// Takes the values `newer` carries (a later reply wins) and its id, times and source;
    /// keeps the values of the fields it does not carry. `fields` becomes the union.
    void merge(const TelemetrySample &newer);

    /// The sample a reply carries, or nullopt for replies without telemetry (model, PID, ack).
    static std::optional<TelemetrySample> fromReply(const protocol::Reply &reply, double time);
    /// The values another master's request commands (0xA0..0xA8), as a sample of its drive
    /// at `time`; nullopt for a request that commands none of them. A torque is given only
    /// when its scale is known: V2.3, or V2.35 with the drive's series known.
    static std::optional<TelemetrySample> fromRequest(const protocol::Request &request,
                                                      std::optional<protocol::Series> series,
                                                      protocol::Generation generation, double time);
    /// The fields only requests carry (fromRequest), never a drive's reply.
    static TelemetryFields commandedFields();
    /// The sample of a 0x9A/0x9B state read outside a reply (a scan's probe).
    static TelemetrySample fromState1(int id, const protocol::State1 &state, double time);
    /// The fields a command's reply carries for a series (nullopt: unknown, read as MF) and
    /// protocol generation: what fromReply() fills from such a reply; none for a command
    /// without telemetry.
    static TelemetryFields fieldsOf(protocol::Command command,
                                    std::optional<protocol::Series> series, bool v235);
};

/// Samples delivered together (at most ~60 batches per second), in arrival order.
using TelemetryBatch = QVector<TelemetrySample>;

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::TelemetrySample)
Q_DECLARE_METATYPE(lk::bus::TelemetryBatch)
