#pragma once

#include <QtCore/QString>

#include <optional>

namespace lk::sim {

/// An optional mechanical resonance: the rotor's inertia split into the motor's and a load's,
/// coupled by a spring with damping (a two-mass system). The total inertia stays the rotor's,
/// so below the resonance the loop answers as without it.
struct MechanicalResonance {
    double hz = 0;         ///< the resonance seen from the motor (its peak); 0: none, one mass
    double damping = 0.05; ///< the coupling's damping ratio
    double loadRatio = 1;  ///< load inertia / motor inertia
    bool enabled() const { return hz > 0; }
    bool operator==(const MechanicalResonance &o) const
    {
        return hz == o.hz && damping == o.damping && loadRatio == o.loadRatio;
    }
};

/// Optional quantisation of what the drive measures.
struct SensorQuantisation {
    /// Encoder counts per turn behind the drive's speed estimate (count differences per
    /// substep, then its low-pass); 0: the exact angle.
    int countsPerTurn = 0;
    double speedResolutionDps = 0; ///< the step of the speed the drive reports; 0: exact
    bool operator==(const SensorQuantisation &o) const
    {
        return countsPerTurn == o.countsPerTurn && speedResolutionDps == o.speedResolutionDps;
    }
};

/// The plant's optional parts, as lksim takes them per drive:
/// "resonance=HZ[/DAMPING[/LOAD_RATIO]]", "counts=N", "speed-res=DPS", "friction=NM", joined
/// by '+' ("resonance=120/0.05+counts=16384").
struct PlantOptions {
    MechanicalResonance resonance;
    SensorQuantisation sensor;
    /// The rotor's Coulomb friction (Nm) instead of the series' (RotorParams); 0: none. A
    /// sine of the angle around a standstill reverses the rotor twice a cycle, where friction
    /// is no part of a linear loop: friction=0 makes the position loop's response the
    /// PositionLoopTransfer's at any amplitude.
    std::optional<double> coulombFrictionNm;

    static constexpr double kMinResonanceHz = 5;
    static constexpr double kMaxResonanceHz = 1500; ///< below the substep's stability bound
    static constexpr double kMaxFrictionNm = 1;

    /// Parse a '+'-joined list; nullopt with one sentence naming the item in `error`.
    static std::optional<PlantOptions> parse(const QString &text, QString *error = nullptr);
    /// Whether `item` is one of ours ("resonance=...", "counts=...", "speed-res=...",
    /// "friction=...").
    static bool isItem(const QString &item);
    /// Take one "key=value" item; false (and `error`) for an unknown key or a bad value.
    bool parseItem(const QString &item, QString *error = nullptr);
    /// Back to text; empty when nothing is set.
    QString toString() const;
    bool operator==(const PlantOptions &o) const
    {
        return resonance == o.resonance && sensor == o.sensor &&
               coulombFrictionNm == o.coulombFrictionNm;
    }
};

/// The rotor's mechanics in one substep, backward Euler in the speeds and the spring's twist
/// from the substep before (semi-implicit: stable for any resonance below kMaxResonanceHz):
///   J1 dw1/dt = T - k twist - c (w1 - w2) - b w1,   J2 dw2/dt = k twist + c (w1 - w2),
///   d twist/dt = w1 - w2.
/// Without a resonance J1 is the whole inertia and w2, twist stay 0. Coulomb friction is not
/// in it (DrivePhysics applies it after; it is no part of the linear loop). Shared by
/// DrivePhysics and SpeedLoopTransfer so that the transfer function is the physics'.
struct TwoMassMechanics {
    double j1 = 1, j2 = 0; ///< kg m^2: the motor's and the load's
    double k = 0, c = 0;   ///< Nm/rad, Nm s/rad: the coupling
    double b = 0;          ///< Nm s/rad: viscous friction on the motor

    TwoMassMechanics() = default;
    TwoMassMechanics(double inertia, double viscous, const MechanicalResonance &resonance);

    struct State {
        double motor = 0, load = 0, twist = 0; ///< rad/s, rad/s, rad
    };
    /// The state after `dt` with `torque` (Nm) on the motor.
    State step(const State &x, double torque, double dt) const;
};

} // namespace lk::sim
