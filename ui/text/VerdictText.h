#pragma once

#include <protocol/Series.h>
#include <safety/MotionGuard.h>
#include <safety/MotionPlanner.h>
#include <tuning/StepTestPlan.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <optional>

namespace lk::text {

/// The one wording of the safety gate's typed verdicts (safety::Verdict, SpeedBound,
/// tuning::StepRefusal), shown by lkstudio (translated) and printed by lkctl (English).
/// Each is a clause without a capital or a full stop, so that the caller frames it:
/// "Refused: %1." in the GUI, "refused for safety, nothing was sent: %1" in lkctl.
class VerdictText {
    Q_DECLARE_TR_FUNCTIONS(lk::text::VerdictText)
public:
    /// How a verdict names a command: by its title ("Open loop power (0xA0)", translated) in
    /// lkstudio, by its CLI.md name ("open_loop") in lkctl, whose output docs/CLI.md pins.
    enum class CommandNames { Titles, Cli };
    /// Titles unless changed: lkctl's main() chooses Cli once, before any thread starts.
    static void setCommandNames(CommandNames names);
    static CommandNames commandNames();

    /// Which limit stopped a command, with both numbers, e.g. "the speed 800 dps is over your
    /// speed limit of 720 dps"; empty when it was allowed.
    static QString verdict(const safety::Verdict &verdict, std::optional<protocol::Series> series);
    /// Which speed bound a command went out with, e.g. "max speed 720 dps (your speed limit)";
    /// empty for SpeedBound::None.
    static QString speedBound(safety::SpeedBound bound, double dps);
    /// A step test's refused setpoint and its limit, e.g. "setpoint 2 of 3 (step, 0 -> 720 dps
    /// at 1 s): the speed 720 dps is over your speed limit of 360 dps"; empty when nothing was
    /// refused.
    static QString stepRefusal(const tuning::StepRefusal &refusal);
    /// "MF" or "unknown series".
    static QString series(std::optional<protocol::Series> series);

    // A listen-only link (bus::LinkMode::ListenOnly): complete sentences, shown as they are.
    /// Why an action that would transmit is disabled: "Listen-only: this tool transmits
    /// nothing. ..."
    static QString listenOnlyNoSend();
    /// An emergency stop asked for while listening: nothing went out, and who must stop.
    static QString listenOnlyStop();
};

} // namespace lk::text
