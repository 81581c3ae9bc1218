#pragma once

#include "DrivePhysics.h"
#include "SimDriveModel.h"
#include "SimProtection.h"
#include "SimRomStore.h"
#include "motor/SeriesLimits.h"
#include "protocol/Reply.h"
#include "protocol/Request.h"

#include <functional>
#include <optional>

namespace lk::sim {

/// One simulated LK drive: parameters in RAM and ROM, motion state, error flags and the
/// physics behind them. Answers typed requests the way the spec and docs/ERRATA.md say a V2.3
/// drive does, or, with a firmware-2.35 model, the way docs/V2.35.md says (silent to the commands
/// its generation lacks). Plain value logic: not thread-safe, owned by one thread.
///
/// Motor on and off (docs/V2.35.md sections 3 and 11): a V2.3 drive is turned on by any control
/// command. A V2.35 drive powers up on; after 0x80 (or a protection trip) it stays off until
/// 0x88, and a control command meanwhile is answered but not acted on; 0x81 is left by a new
/// control command. Its holding brake (0x8C) holds the shaft while engaged; it powers up
/// released. Protection faults (SimProtection, and the model's scheduled SimFaults) switch the
/// output off as 0x80 does.
class SimDrive {
public:
    enum class RunState { Off, Running, Stopped };
    static constexpr double kOverTemperatureC = SimProtection::kOverTemperatureC;
    static constexpr double kOverTemperatureClearC = SimProtection::kOverTemperatureClearC;

    using RomWrittenHandler = std::function<void(int id, protocol::Series, const SimRom &)>;

    /// `rom`: what a ROM store kept for the drive; nullopt: the model's factory ROM.
    SimDrive(int id, const SimDriveModel &model, const std::optional<SimRom> &rom = std::nullopt);

    int id() const { return m_id; }
    const SimDriveModel &model() const { return m_model; }
    protocol::Series series() const { return m_model.series; }
    protocol::Generation generation() const { return m_model.generation; }
    protocol::DecodeContext context() const { return {series(), generation()}; }
    const motor::SeriesLimits &limits() const { return m_limits; }
    double gearRatio() const { return m_gearRatio; }
    int encoderCountsPerTurn() const { return m_counts; }

    /// Answer one request addressed to this drive. nullopt = the drive stays silent (the
    /// series does not implement the command, or the request is for another ID).
    std::optional<protocol::Reply> handle(const protocol::Request &request);
    /// Let simulated time pass (any interval; long gaps are capped at one minute).
    void advance(double seconds);
    /// Power cycle: RAM reloads from ROM (0x19 zero applied), angles restart from the encoder,
    /// the drive is off with no command, error flags show only present causes.
    void restart();

    // What the protocol exposes.
    RunState runState() const { return m_runState; }
    /// The motor state 0x9A reports on V2.35: on unless switched off (0x80, a trip).
    bool motorOn() const { return m_runState != RunState::Off; }
    std::optional<protocol::Command> activeCommand() const { return m_activeCommand; }
    protocol::PidGains ramPid() const { return m_ramPid; }
    const SimParams &ramParams() const { return m_ramParams; } ///< V2.35 drives
    bool brakeReleased() const { return m_brakeReleased; }
    qint32 accelerationDps2() const { return m_ramAccel; }
    const SimRom &rom() const { return m_rom; }
    quint8 errorState() const { return m_protection.errorState(); }
    /// Seconds since power-up (the clock of the model's scheduled faults).
    double uptimeS() const { return m_protection.uptimeS(); }
    quint16 encoderRaw() const;
    quint16 encoder() const;
    quint16 encoderOffset() const { return m_encoderOffset; }
    qint64 multiTurnRaw() const;   ///< 0.01 deg
    quint32 singleTurnRaw() const; ///< 0.01 deg, 0 .. 36000 x ratio - 1
    double speedDps() const { return m_physics.speedDps(); }
    double iqA() const { return m_physics.currentA(); }
    qint16 iqRaw() const;
    qint16 powerRaw() const; ///< MS output power -1000..1000 (duty of the supply)
    double temperatureC() const { return m_physics.temperatureC(); }
    double busVoltage() const { return m_physics.supplyVoltage(); }

    protocol::State1 state1() const;
    protocol::State2 state2() const;
    protocol::State3 state3() const;
    protocol::EncoderReading encoderReading() const;
    protocol::ModelInfo modelInfo() const;

    // Bench knobs for tests, demos and lksim options.
    void setSupplyVoltage(double volts);
    void setTemperatureC(double celsius) { m_physics.setTemperatureC(celsius); }
    void setLoadTorque(double nm) { m_physics.setLoadTorque(nm); }
    void setRotorLocked(bool locked);
    /// Newer firmware answers 0x19 with LEN 2 (the new zero); V2.3 echoes (default).
    void setZeroReplyCarriesOffset(bool on) { m_zeroReplyWithOffset = on; }

    // What some links and generations do beside a command's common effect (SimCanFront).
    /// The turn count goes, the angle within the (output) turn stays (0x93; CAN V2.36's 0x80).
    void clearTurnCount();
    /// The current position reads `raw` (0.01 deg) from now on, in RAM (CAN V2.36's 0x95).
    void setMultiTurnAngle(qint64 raw);
    void setRomWrittenHandler(RomWrittenHandler handler) { m_romWritten = std::move(handler); }
    const DrivePhysics &physics() const { return m_physics; }

private:
    std::optional<protocol::Reply> handleParameter(const protocol::Request &r);
    std::optional<protocol::Reply> handleV235(const protocol::Request &r);
    void applyParams();
    std::optional<protocol::Reply> handleRead(const protocol::Request &r);
    std::optional<protocol::Reply> handleRunState(const protocol::Request &r);
    protocol::Reply handleMotion(const protocol::Request &r);
    std::optional<LoopTarget> motionTarget(const protocol::Request &r) const;
    double singleTurnTargetDeg(const protocol::SinglePositionCommand &c) const;
    double maxSpeedFor(const std::optional<quint32> &maxSpeedRaw) const;
    bool isV235() const { return generation() == protocol::Generation::V2_35; }
    void checkProtection();
    void holdShaft();
    void switchOff();
    void applyOutput();
    void resetAngleReference();
    void writeRom();

    int m_id;
    SimDriveModel m_model;
    const motor::SeriesLimits &m_limits;
    double m_gearRatio = 1.0;
    int m_counts = 16384;
    DrivePhysics m_physics;

    SimRom m_rom;
    protocol::PidGains m_ramPid;
    qint32 m_ramAccel = 0;
    SimParams m_ramParams;
    bool m_brakeReleased = false; ///< V2.35: engaged, the brake holds the shaft
    bool m_rotorLocked = false;   ///< the bench's blocked rotor (setRotorLocked)
    quint16 m_encoderOffset = 0;
    double m_refDeg = 0; ///< physics angle where multi-turn and single-turn angles are zero

    RunState m_runState = RunState::Off;
    LoopTarget m_command; ///< the stored control command (kept by 0x81, cleared by 0x80)
    std::optional<protocol::Command> m_activeCommand;
    SimProtection m_protection;
    bool m_zeroReplyWithOffset = false;
    RomWrittenHandler m_romWritten;
};

} // namespace lk::sim
