#pragma once

#include "StepTrace.h"

#include <protocol/Request.h>
#include <protocol/Series.h>
#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// A step test as the user asks for it. FROM and TO are both the user's: the drive is taken to
/// FROM first and held there (the pre-roll), then the step(s) go FROM -> TO (-> FROM ...).
struct StepTestSpec {
    int id = 1;
    StepLoop loop = StepLoop::Speed;
    double from = 0; ///< dps (speed) or multi-turn rotor deg (position)
    double to = 0;
    double durationS = 1; ///< how long each step (each half-period of a square) is held
    int periods = 1;      ///< 1: one step FROM -> TO; N > 1: a square of N periods (2N edges)
    double preRollS = 1;  ///< how long the drive is held at FROM before the first edge
    /// Position only: a max speed below the speed limit (MotionPlanner's UserMaxSpeed);
    /// nullopt: the speed limit (or the series top speed, if lower).
    std::optional<double> maxSpeedDps;

    static constexpr double kMaxDurationS = 60; ///< per step, and for the pre-roll
    static constexpr int kMaxPeriods = 100;
    static constexpr double kMinDurationS = 0.01; ///< a few bus transactions at 115200
};

/// One timed setpoint of a planned step test.
struct StepSetpoint {
    enum class Role {
        PreRoll, ///< to FROM, before the first edge
        Edge,    ///< a step under test (a StepEdge of the trace)
        Return,  ///< speed test, single step: back to FROM at the end
    };
    Role role = Role::Edge;
    double atS = 0;            ///< when to send it, seconds from the start of the test
    double target = 0;         ///< dps or deg
    double previous = 0;       ///< the target before it (an edge's `from`)
    protocol::Request request; ///< as MotionPlanner made it (position: 0xA4 with its max speed)
};

/// Which setpoint of a planned step test a limit refused, and the verdict: typed data that
/// VerdictText::stepRefusal words for lkstudio and lkctl.
struct StepRefusal {
    safety::Verdict verdict; ///< kind None: nothing was refused by a limit
    int index = -1;          ///< the refused setpoint, 0-based
    int count = 0;           ///< how many setpoints the test has
    StepSetpoint setpoint;   ///< the refused one (no request)
    StepLoop loop = StepLoop::Speed;
    std::optional<protocol::Series> series; ///< the series the plan was checked against
};

/// The timed setpoints of one step test, every one of them checked by safety::MotionPlanner
/// before anything is sent (speed bound, series and soft limits; each position target within
/// one output turn of the drive's read angle or of the target before it), or the refusal of
/// the first one that failed, in which case there are no setpoints at all. Pure.
///
/// Timeline: FROM at 0 (pre-roll); the first edge at preRollS; a square's edges every
/// durationS after it, alternating TO and FROM, so it ends at FROM; the test ends durationS
/// after the last edge. A single speed step goes back to FROM at its end (Role::Return); a
/// single position step stays at TO. A speed test leaves the drive turning at FROM.
class StepTestPlan {
public:
    static StepTestPlan make(const StepTestSpec &spec, std::optional<protocol::Series> series,
                             const safety::SoftLimits &limits,
                             const safety::DrivePosition &position);
    /// What is wrong with a spec before any limit is looked at (English, naming the value),
    /// or an empty string. make() refuses such a spec with this text in specError().
    static QString checkSpec(const StepTestSpec &spec);
    /// The command a test of `loop` sends: speed (0xA2) or multi_position_limited (0xA4).
    static protocol::Command commandOf(StepLoop loop);

    bool allowed() const { return !m_setpoints.isEmpty(); }
    const StepTestSpec &spec() const { return m_spec; }
    const QVector<StepSetpoint> &setpoints() const { return m_setpoints; }
    /// The limit that refused the test (kind None when allowed or when the spec was bad).
    const safety::Verdict &verdict() const { return m_refusal.verdict; }
    const QString &specError() const { return m_specError; }
    /// The setpoint a limit refused, with the verdict (verdict kind None when allowed or when
    /// the spec was bad).
    const StepRefusal &refusal() const { return m_refusal; }
    /// Which speed bound the commands went out with (MotionPlanner's; the same for each).
    safety::SpeedBound bound() const { return m_bound; }
    double boundDps() const { return m_boundDps; }
    /// When the test ends, seconds from its start (the last setpoint's hold is over).
    double endS() const { return m_endS; }

private:
    StepTestSpec m_spec;
    QVector<StepSetpoint> m_setpoints;
    QString m_specError;
    StepRefusal m_refusal;
    safety::SpeedBound m_bound = safety::SpeedBound::None;
    double m_boundDps = 0;
    double m_endS = 0;
};

} // namespace lk::tuning
