#pragma once

#include "PlantOptions.h"
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
    /// Speed: a tighter bound on the speed loop's current than the drive's own (CAN V2.36's
    /// 0xA2 torque limit); 0: none.
    double currentLimitA = 0;
};

/// Derivative gains of the three loops (V2.35's Kd, 0..65535; V2.3 drives have none).
struct DerivativeGains {
    quint16 angleKd = 0, speedKd = 0, iqKd = 0;
};

/// The loops' gains in physical units, as DrivePhysics derives them from the drive's gains
/// (SpeedLoopTransfer builds the speed loop's transfer function from them).
struct PhysicalGains {
    double kpPos = 0, kiPos = 0, kdPos = 0;       ///< 1/s, 1/s^2, dimensionless
    double kpSpeed = 0, kiSpeed = 0, kdSpeed = 0; ///< A per rad/s, per rad, per rad/s^2
    double kpIq = 0, kiIq = 0, kdIq = 0;          ///< V/A, V/(A s), H
};

/// Rotor, winding and cascaded PID loops of one drive, as the firmware runs them.
///
/// Everything is integrated in fixed 0.2 ms substeps (the drives' loop rate), SI units on the
/// rotor side:
/// - Mechanics: J dw/dt = Kt i - b w - Tc sgn(w) - Tload. Coulomb friction Tc holds the rotor
///   while the torque cannot overcome it; the speed is capped at the series maximum.
/// - Winding (q axis): L di/dt = v - R i - Ke w with Ke = Kt, |v| <= the supply voltage.
/// - Current loop: v = PI(iRef - i) - Kd di/dt + Ke w (back-EMF feed-forward, as FOC drives
///   do). Loop and winding are solved together by backward Euler, so any gain and any
///   advance() interval stays bounded; at the voltage limit its integrator freezes.
/// - Speed loop: iRef = PI(wRef - w_est) - Kd dw_est/dt, clamped at the drive's current
///   limit with its integrator frozen there. w_est is the drive's speed estimate: the true
///   speed through a 0.8 ms low-pass, as encoder differences are filtered on a real drive
///   (telemetry reports the true speed). wRef follows the command at the acceleration
///   setting (V2.3 0x34, V2.35 speed ramp 0x9E; 0 = no limit).
/// - Position loop: wCmd = PI(target - angle) - Kd w_est, bounded by the max speed and by
///   sqrt(2 a |error|) so that it can stop in time (a = the acceleration setting or half the
///   current-limited acceleration).
///
/// Gain scaling (setGains(), setDerivativeGains()): the drive's 0..255 gains; V2.35's uint16
/// parameter gains saturate at 255. J, Kt, R, L are the RotorParams.
/// - current: Kp = iqKp/50 x L x 2000/s, Ki = iqKi/50 x R x 2000/s. At 50/50 the zero cancels
///   the winding's pole: a first-order current loop of 2000 rad/s.
/// - speed: Kp = speedKp x 4/s x J/Kt (A per rad/s), Ki = speedKi x 150/s^2 x J/Kt, so that
///   speedKp is the loop's bandwidth in units of 4 rad/s whatever the motor: the default 50
///   gives 200 rad/s with the PI zero at 30 rad/s (Ki 40).
/// - angle: Kp = angleKp x 0.6/s (rad/s of speed command per rad), Ki = angleKi x 0.2/s^2;
///   the default 100 gives 60 rad/s.
/// - Kd (V2.35 only): speed Kd x 0.002 x J/Kt (acceleration feedback, 255 = about half the
///   rotor inertia), angle Kd x 0.004 (speed feedback, 255 halves the angle loop's
///   bandwidth), current Kd x 0.002 x L (255 = 50 % more inductance).
///
/// Optional plant parts (setPlantOptions(), PlantOptions): a mechanical resonance (the inertia
/// split into motor and load coupled by a damped spring, TwoMassMechanics), encoder counts
/// behind the speed estimate (count differences per substep, whose linear part is the speed
/// itself: they add noise, not a change of the loop's transfer function) and the reported
/// speed's resolution. None is set by default.
///
/// Why it answers like a real drive: the speed filter, the current loop and the substep add
/// lag, so the speed loop's phase margin shrinks as speedKp grows. At the factory gains a
/// speed step overshoots about 5 %; from about speedKp 100 overshoot grows; at 255 it rings
/// (40-55 %, several swings) but stays bounded. A low speedKp with the default Ki swings
/// slowly (a PI with too little damping); without Ki friction and load leave a speed error.
/// The angle loop overshoots likewise once its bandwidth nears the speed loop's (angleKp
/// above about 200); Kd damps both.
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
    /// Resonance and sensor quantisation; the rotor's motion goes on from where it is.
    void setPlantOptions(const PlantOptions &options);
    const PlantOptions &plantOptions() const { return m_plant; }
    /// The mechanics' coefficients (SpeedLoopTransfer's).
    const TwoMassMechanics &mechanicsModel() const { return m_mechanics; }

    void advance(double seconds);

    double positionDeg() const;
    double speedDps() const;     ///< the motor's, at the reported resolution if one is set
    double loadSpeedDps() const; ///< the load's beyond the resonance; the motor's without one
    double currentA() const { return m_current; }
    double voltage() const { return m_voltage; }
    double temperatureC() const { return m_temperature; }
    double electricalAngleRad() const;
    const RotorParams &params() const { return m_params; }
    PhysicalGains physicalGains() const;
    /// Time constant of the drive's speed estimate (a first-order low-pass from encoder
    /// differences): its lag, with the current loop's, is what makes a too stiff loop ring.
    static constexpr double kSpeedFilterSeconds = 0.0008;

private:
    void step(double dt);
    double outerLoops(double dt); ///< current reference (A) of Speed/Position modes
    double speedLoop(double omegaRef, double dt);
    double slewSpeedReference(double omegaCmd, double dt);
    void currentLoop(double iRef, double dt);
    void openWinding(double volts, double dt);
    void mechanics(double dt);
    void measureSpeed();
    double countedAngle(double theta) const; ///< rad, down to the encoder's count
    double coulombFriction() const;          ///< Nm: the plant option's, else the rotor's
    void thermal(double dt);
    bool atRest() const;
    void resetIntegrators();

    RotorParams m_params;
    PlantOptions m_plant;
    TwoMassMechanics m_mechanics;
    double m_currentLimit;
    double m_speedLimit; ///< rad/s, hard cap of the rotor
    double m_supplyV = 24;
    LoopTarget m_target;

    // Physical gains derived from the uint8 gains (see setGains()).
    double m_kpPos = 0, m_kiPos = 0, m_kpSpeed = 0, m_kiSpeed = 0, m_kpIq = 0, m_kiIq = 0;
    double m_kdPos = 0, m_kdSpeed = 0, m_kdIq = 0;
    double m_accel = 0; ///< rad/s^2, 0 = unlimited

    double m_theta = 0;         ///< rad, continuous
    double m_omega = 0;         ///< rad/s
    double m_omegaLoad = 0;     ///< rad/s, the load beyond the resonance
    double m_twist = 0;         ///< rad, the coupling's
    double m_countedTheta = 0;  ///< rad, the angle as the encoder counted it last substep
    double m_omegaMeasured = 0; ///< rad/s, the drive's filtered speed estimate
    double m_accelMeasured = 0; ///< rad/s^2, its change per substep
    double m_current = 0;       ///< A (q axis)
    double m_voltage = 0;       ///< V applied (q axis)
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
