#include "DrivePhysics.h"

#include <QtCore/QtGlobal>

#include <algorithm>
#include <cmath>

namespace lk::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;

// Gain scaling: the defaults (angle 100/100, speed 50/40, iq 50/50) give a current loop of
// about 2000 rad/s, a speed loop of about 200 rad/s and a position loop of about 50 rad/s.
constexpr double kDefaultIqGain = 50.0;
constexpr double kCurrentBandwidth = 2000.0;   // rad/s at the default iq gains
constexpr double kSpeedBandwidthPerUnit = 4.0; // rad/s per unit of speed Kp
constexpr double kSpeedKiPerUnit = 150.0;      // rad/s^2 per unit of speed Ki
constexpr double kPosKpPerUnit = 0.6;          // 1/s per unit of angle Kp
constexpr double kPosKiPerUnit = 0.2;          // 1/s^2 per unit of angle Ki
// Derivative gains (V2.35 Kd), saturated at 255 like the others: at 255 the speed loop's
// acceleration feedback equals about half the rotor inertia, the angle loop's speed feedback
// halves its bandwidth, and the current loop's acts like 50 % more inductance.
constexpr double kMaxDerivativeUnits = 255.0;
constexpr double kSpeedKdPerUnit = 0.002; // of J/Kt (A per rad/s^2)
constexpr double kPosKdPerUnit = 0.004;   // dimensionless speed feedback
constexpr double kIqKdPerUnit = 0.002;    // of the winding inductance

// Longest interval simulated in one call: a caller that forgets the simulator for hours must
// not stall its thread for seconds catching up.
constexpr double kMaxCatchUpSeconds = 60.0;
// Decelerating towards a position target with no acceleration limit uses this share of the
// peak acceleration, so that friction and the current loop lag do not make it overshoot.
constexpr double kDecelMargin = 0.5;

double clampAbs(double v, double limit)
{
    return std::clamp(v, -limit, limit);
}
} // namespace

DrivePhysics::DrivePhysics(const RotorParams &params, double currentLimitA, double speedLimitDps)
    : m_params(params), m_mechanics(params.inertia, params.viscousFriction, {}),
      m_currentLimit(currentLimitA), m_speedLimit(speedLimitDps * kRadPerDeg)
{
    setGains({});
}

void DrivePhysics::setPlantOptions(const PlantOptions &options)
{
    m_plant = options;
    m_mechanics = TwoMassMechanics(m_params.inertia, m_params.viscousFriction, options.resonance);
    if (!options.resonance.enabled()) {
        m_omegaLoad = 0;
        m_twist = 0;
    } else if (m_twist == 0) {
        m_omegaLoad = m_omega; // the load was turning with the rigid rotor
    }
    m_countedTheta = countedAngle(m_theta);
}

double DrivePhysics::coulombFriction() const
{
    return m_plant.coulombFrictionNm.value_or(m_params.coulombFriction);
}

double DrivePhysics::countedAngle(double theta) const
{
    const int counts = m_plant.sensor.countsPerTurn;
    if (counts <= 0)
        return theta;
    const double count = 2.0 * kPi / counts;
    return std::floor(theta / count) * count;
}

void DrivePhysics::setGains(const protocol::PidGains &g)
{
    const double inertiaPerKt = m_params.inertia / m_params.torqueConstant;
    m_kpIq = g.iqKp / kDefaultIqGain * m_params.inductance * kCurrentBandwidth;
    m_kiIq = g.iqKi / kDefaultIqGain * m_params.resistance * kCurrentBandwidth;
    m_kpSpeed = g.speedKp * kSpeedBandwidthPerUnit * inertiaPerKt;
    m_kiSpeed = g.speedKi * kSpeedKiPerUnit * inertiaPerKt;
    m_kpPos = g.angleKp * kPosKpPerUnit;
    m_kiPos = g.angleKi * kPosKiPerUnit;
}

PhysicalGains DrivePhysics::physicalGains() const
{
    return {m_kpPos, m_kiPos, m_kdPos, m_kpSpeed, m_kiSpeed, m_kdSpeed, m_kpIq, m_kiIq, m_kdIq};
}

void DrivePhysics::setDerivativeGains(const DerivativeGains &kd)
{
    auto units = [](quint16 v) { return std::min<double>(v, kMaxDerivativeUnits); };
    m_kdSpeed = units(kd.speedKd) * kSpeedKdPerUnit * m_params.inertia / m_params.torqueConstant;
    m_kdPos = units(kd.angleKd) * kPosKdPerUnit;
    m_kdIq = units(kd.iqKd) * kIqKdPerUnit * m_params.inductance;
}

void DrivePhysics::setAccelerationDps2(double accel)
{
    m_accel = accel > 0 ? accel * kRadPerDeg : 0.0;
}

void DrivePhysics::setTarget(const LoopTarget &target)
{
    if (target.mode != m_target.mode) {
        resetIntegrators();
        m_omegaRef = m_omega; // bumpless start from the present speed
    }
    m_target = target;
}

void DrivePhysics::setPositionDeg(double deg)
{
    m_theta = deg * kRadPerDeg;
    m_countedTheta = countedAngle(m_theta);
}

double DrivePhysics::positionDeg() const
{
    return m_theta / kRadPerDeg;
}

double DrivePhysics::speedDps() const
{
    const double dps = m_omega / kRadPerDeg;
    const double step = m_plant.sensor.speedResolutionDps;
    return step > 0 ? std::round(dps / step) * step : dps;
}

double DrivePhysics::loadSpeedDps() const
{
    return (m_mechanics.j2 > 0 ? m_omegaLoad : m_omega) / kRadPerDeg;
}

double DrivePhysics::electricalAngleRad() const
{
    const double e = std::fmod(m_theta * m_params.polePairs, 2.0 * kPi);
    return e < 0 ? e + 2.0 * kPi : e;
}

void DrivePhysics::resetIntegrators()
{
    m_iqIntegral = 0;
    m_speedIntegral = 0;
    m_posIntegral = 0;
}

bool DrivePhysics::atRest() const
{
    return m_target.mode == LoopMode::Off && m_omega == 0.0 && m_current == 0.0 &&
           m_omegaLoad == 0.0 && m_twist == 0.0 &&
           (m_locked || std::abs(m_loadTorque) <= coulombFriction());
}

void DrivePhysics::advance(double seconds)
{
    if (!(seconds > 0))
        return; // also refuses NaN
    seconds = std::min(seconds, kMaxCatchUpSeconds);
    m_pendingTime += seconds;
    auto steps = static_cast<qint64>(std::floor(m_pendingTime / kStepSeconds + 1e-9));
    m_pendingTime = std::max(0.0, m_pendingTime - static_cast<double>(steps) * kStepSeconds);
    while (steps > 0 && !atRest()) {
        step(kStepSeconds);
        --steps;
    }
    if (steps > 0) {
        // Nothing moves: only the winding cools, which has a closed form.
        m_omegaMeasured = m_omega;
        m_accelMeasured = 0;
        const double tau = m_params.thermalCapacity * m_params.thermalResistance;
        const double t = static_cast<double>(steps) * kStepSeconds;
        m_temperature = kAmbientC + (m_temperature - kAmbientC) * std::exp(-t / tau);
        m_voltage = 0;
    }
}

void DrivePhysics::step(double dt)
{
    switch (m_target.mode) {
    case LoopMode::Off:
        m_current = 0;
        m_voltage = 0;
        m_omegaRef = m_omega;
        resetIntegrators();
        break;
    case LoopMode::OpenLoop:
        openWinding(std::clamp(m_target.voltageFraction, -1.0, 1.0) * std::max(0.0, m_supplyV), dt);
        break;
    case LoopMode::Torque:
        currentLoop(m_target.currentA, dt); // not limited by the drive (ERRATA)
        break;
    case LoopMode::Speed:
    case LoopMode::Position:
        currentLoop(outerLoops(dt), dt);
        break;
    }
    mechanics(dt);
    measureSpeed();
    thermal(dt);
}

double DrivePhysics::outerLoops(double dt)
{
    const double limit = std::min(std::max(0.0, m_target.maxSpeedDps) * kRadPerDeg, m_speedLimit);
    double command = 0;
    if (m_target.mode == LoopMode::Speed) {
        command = clampAbs(m_target.speedDps * kRadPerDeg, limit);
    } else {
        const double error = m_target.positionDeg * kRadPerDeg - m_theta;
        const double raw = m_kpPos * error + m_kiPos * m_posIntegral - m_kdPos * m_omegaMeasured;
        const double peakAccel =
            m_params.torqueConstant * m_currentLimit / m_params.inertia * kDecelMargin;
        const double decel = m_accel > 0 ? std::min(m_accel, peakAccel) : peakAccel;
        // Never faster than what still allows stopping at the target with the allowed
        // deceleration: a trapezoidal profile without planning ahead.
        const double bound = std::min(limit, std::sqrt(2.0 * decel * std::abs(error)));
        command = clampAbs(raw, bound);
        if (std::abs(raw) < bound)
            m_posIntegral += error * dt;
    }
    return speedLoop(slewSpeedReference(command, dt), dt);
}

double DrivePhysics::slewSpeedReference(double omegaCmd, double dt)
{
    if (m_accel <= 0) {
        m_omegaRef = omegaCmd;
    } else {
        m_omegaRef += clampAbs(omegaCmd - m_omegaRef, m_accel * dt);
    }
    return m_omegaRef;
}

double DrivePhysics::speedLoop(double omegaRef, double dt)
{
    // Kd acts on the measured acceleration (derivative on measurement: no kick on a step).
    const double error = omegaRef - m_omegaMeasured;
    const double out = m_kpSpeed * error + m_kiSpeed * (m_speedIntegral + error * dt) -
                       m_kdSpeed * m_accelMeasured;
    const double limit = m_target.currentLimitA > 0
                             ? std::min(m_target.currentLimitA, m_currentLimit)
                             : m_currentLimit;
    if (std::abs(out) > limit)
        return clampAbs(out, limit); // saturated: integrator frozen (anti-windup)
    m_speedIntegral += error * dt;
    return out;
}

void DrivePhysics::currentLoop(double iRef, double dt)
{
    // v = PI(iRef - i) - Kd di/dt + Ke w (back-EMF feed-forward, as FOC drives do), on
    // L di/dt = v - R i - Ke w, solved by backward Euler: unconditionally stable for any
    // non-negative gains, whatever the substep. The feed-forward cancels in the solution.
    const double a = (m_params.inductance + m_kdIq) / dt;
    const double emf = m_params.torqueConstant * m_omega;
    const double denom = a + m_params.resistance + m_kpIq + m_kiIq * dt;
    double i = (a * m_current + m_kpIq * iRef + m_kiIq * (m_iqIntegral + dt * iRef)) / denom;
    double v = m_kpIq * (iRef - i) + m_kiIq * (m_iqIntegral + dt * (iRef - i)) -
               m_kdIq * (i - m_current) / dt + emf;
    const double vMax = std::max(0.0, m_supplyV);
    if (std::abs(v) > vMax) {
        v = clampAbs(v, vMax); // voltage-limited: integrator frozen
        const double l = m_params.inductance / dt;
        i = (l * m_current + v - emf) / (l + m_params.resistance);
    } else {
        m_iqIntegral += dt * (iRef - i);
    }
    m_current = i;
    m_voltage = v;
}

void DrivePhysics::openWinding(double volts, double dt)
{
    const double a = m_params.inductance / dt;
    const double emf = m_params.torqueConstant * m_omega;
    m_current = (a * m_current + volts - emf) / (a + m_params.resistance);
    m_voltage = volts;
}

void DrivePhysics::mechanics(double dt)
{
    if (m_locked) {
        m_omega = 0;
        m_omegaLoad = 0;
        m_twist = 0;
        return;
    }
    const double torque = m_params.torqueConstant * m_current - m_loadTorque;
    const TwoMassMechanics::State before{m_omega, m_omegaLoad, m_twist};
    TwoMassMechanics::State x = m_mechanics.step(before, torque, dt);
    // Coulomb friction never reverses the motion within a step: that is what makes it stick.
    double w = x.motor;
    const double dw = coulombFriction() * dt / m_mechanics.j1;
    if (w > dw)
        w -= dw;
    else if (w < -dw)
        w += dw;
    else
        w = 0;
    w = clampAbs(w, m_speedLimit);
    m_theta += w * dt;
    m_omega = w;
    if (m_mechanics.j2 > 0) {
        m_twist = before.twist + dt * (w - x.load);
        m_omegaLoad = x.load;
        // A load swinging down to nothing on a stuck rotor: at rest, not a denormal forever.
        if (w == 0 && std::abs(m_omegaLoad) < 1e-9 && std::abs(m_twist) < 1e-12) {
            m_omegaLoad = 0;
            m_twist = 0;
        }
    }
}

void DrivePhysics::measureSpeed()
{
    // Once per substep: the filter's constants fold at compile time. With encoder counts the
    // raw speed is the counted angle's difference over the substep.
    constexpr double gain = kStepSeconds / (kSpeedFilterSeconds + kStepSeconds);
    double raw = m_omega;
    if (m_plant.sensor.countsPerTurn > 0) {
        const double counted = countedAngle(m_theta);
        raw = (counted - m_countedTheta) * (1.0 / kStepSeconds);
        m_countedTheta = counted;
    }
    const double before = m_omegaMeasured;
    m_omegaMeasured += (raw - m_omegaMeasured) * gain;
    m_accelMeasured = (m_omegaMeasured - before) * (1.0 / kStepSeconds);
}

void DrivePhysics::thermal(double dt)
{
    const double heat = m_current * m_current * m_params.resistance;
    const double cooling = (m_temperature - kAmbientC) / m_params.thermalResistance;
    m_temperature += dt * (heat - cooling) / m_params.thermalCapacity;
}

} // namespace lk::sim
