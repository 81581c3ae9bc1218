#pragma once

#include "RotorParams.h"
#include "protocol/Values.h"

namespace lk::sim {

/// What the drive's output stage is asked to do; the cascade runs from the chosen level down.
enum class LoopMode {
    Off,      ///< inverter off: no current, the rotor coasts
    OpenLoop, ///< fixed voltage fraction of the supply (MS 0xA0), no current loop
    Torque,   ///< current loop only, reference not limited (0xA1)
    Speed,    ///< speed -> current
    Position, ///< position -> speed -> current
};

/// The reference of the active loop, in physical units.
struct LoopTarget {
    LoopMode mode = LoopMode::Off;
    double voltageFraction = 0; ///< OpenLoop: -1..1 of the supply
    double currentA = 0;        ///< Torque
    double speedDps = 0;        ///< Speed
    double positionDeg = 0;     ///< Position: absolute rotor angle (physics frame)
    double maxSpeedDps = 0;     ///< Speed/Position: limit, already capped by the series maximum
};

/// Derivative gains of the three loops (V2.35's Kd, 0..65535; V2.3 drives have none).
struct DerivativeGains {
    quint16 angleKd = 0, speedKd = 0, iqKd = 0;
};

/// Rotor, winding and cascaded PI loops of one drive.
///
/// Integrates in fixed 0.2 ms substeps (the loops run at that rate, like drive firmware),
/// with the current loop and the winding solved implicitly (backward Euler) so that any gain
/// 0..255 and any advance() interval stays bounded. Gains are the drive's uint8 PI gains,
/// scaled so that the defaults give a well-damped response; larger gains make the loops faster
/// and eventually oscillate, as on a real drive.
class DrivePhysics {
public:
    static constexpr double kStepSeconds = 0.0002;
    static constexpr double kAmbientC = 25.0;

    DrivePhysics(const RotorParams &params, double currentLimitA, double speedLimitDps);

    void setGains(const protocol::PidGains &gains);
    void setDerivativeGains(const DerivativeGains &kd);
    /// dps/s applied to speed references; 0 or less means no limit.
    void setAccelerationDps2(double accel);
    void setSupplyVoltage(double volts) { m_supplyV = volts; }
    double supplyVoltage() const { return m_supplyV; }
    /// Changes the reference; integrators restart when the loop mode changes.
    void setTarget(const LoopTarget &target);
    const LoopTarget &target() const { return m_target; }
    /// Constant external torque (Nm) against positive rotation, e.g. a load on the shaft.
    void setLoadTorque(double nm) { m_loadTorque = nm; }
    /// A blocked rotor: speed stays zero whatever the torque (stall tests, heating).
    void setRotorLocked(bool locked) { m_locked = locked; }
    void setTemperatureC(double c) { m_temperature = c; }
    void setPositionDeg(double deg);

    void advance(double seconds);

    double positionDeg() const;
    double speedDps() const;
    double currentA() const { return m_current; }
    double voltage() const { return m_voltage; }
    double temperatureC() const { return m_temperature; }
    double electricalAngleRad() const;
    const RotorParams &params() const { return m_params; }

private:
    void step(double dt);
    double outerLoops(double dt); ///< current reference (A) of Speed/Position modes
    double speedLoop(double omegaRef, double dt);
    double slewSpeedReference(double omegaCmd, double dt);
    void currentLoop(double iRef, double dt);
    void openWinding(double volts, double dt);
    void mechanics(double dt);
    void measureSpeed(double dt);
    void thermal(double dt);
    bool atRest() const;
    void resetIntegrators();

    RotorParams m_params;
    double m_currentLimit;
    double m_speedLimit; ///< rad/s, hard cap of the rotor
    double m_supplyV = 24;
    LoopTarget m_target;

    // Physical gains derived from the uint8 gains (see setGains()).
    double m_kpPos = 0, m_kiPos = 0, m_kpSpeed = 0, m_kiSpeed = 0, m_kpIq = 0, m_kiIq = 0;
    double m_kdPos = 0, m_kdSpeed = 0, m_kdIq = 0;
    double m_accel = 0; ///< rad/s^2, 0 = unlimited

    double m_theta = 0;   ///< rad, continuous
    double m_omega = 0;   ///< rad/s
    double m_omegaMeasured = 0; ///< rad/s, the drive's filtered speed estimate
    double m_accelMeasured = 0; ///< rad/s^2, its change per substep
    double m_current = 0; ///< A (q axis)
    double m_voltage = 0; ///< V applied (q axis)
    double m_temperature = kAmbientC;
    double m_loadTorque = 0;
    bool m_locked = false;

    double m_iqIntegral = 0;    ///< A s
    double m_speedIntegral = 0; ///< rad
    double m_posIntegral = 0;   ///< rad s
    double m_omegaRef = 0;      ///< rad/s after the acceleration limit
    double m_pendingTime = 0;   ///< advance() remainder shorter than one substep
};

} // namespace lk::sim
