#pragma once

#include "MotionGuard.h"
#include "SoftLimits.h"

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QSet>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <functional>
#include <optional>

namespace lk::safety {

/// Why a multi-motor torque frame (0x280) may not go out, before or beside the soft limits.
enum class MultiTorqueProblem {
    None,              ///< allowed
    NoDrive,           ///< no drive named
    TooManyDrives,     ///< more than four
    IdOutOfRange,      ///< the frame has slots for IDs 1..4 only
    DuplicateId,       ///< an ID named twice
    UnnamedDrive,      ///< a drive of ID 1..4 on the bus, not named: it would get 0 A
    NotTorque,         ///< an entry that is not a torque request
    NotCan,            ///< RS485 has no such frame
    UnknownGeneration, ///< the drive's CAN generation is not known
    V236,              ///< CAN V2.36 documents no multi-motor frame
    Limit,             ///< MotionGuard refused the drive's torque (`verdict` says which limit)
};

/// The outcome of MultiTorqueGuard::check(): allowed, or the first drive refused and why.
struct MultiTorqueVerdict {
    MultiTorqueProblem problem = MultiTorqueProblem::None;
    int id = 0;      ///< the drive refused (0: the frame as a whole)
    Verdict verdict; ///< Limit: the limit and both numbers, as for a single torque command
    bool allowed() const { return problem == MultiTorqueProblem::None; }
};

/// What the guard must know of one drive named in the frame.
struct MultiTorqueDrive {
    std::optional<protocol::Series> series;         ///< nullopt: unknown (refused)
    std::optional<protocol::Generation> generation; ///< nullopt: unknown (refused)
    SoftLimits limits;
};

/// The gate of the old CAN generation's multi-motor torque frame (docs/CAN.md section 4.2): one
/// frame gives up to four drives (IDs 1..4) their torque, so every drive is checked as a
/// single torque command would be (MotionGuard: its series known, its series' current, its
/// own torque limit), and the frame is refused as a whole when any drive is, naming that drive:
/// nothing is sent to any of them. The frame exists on the old CAN generation only.
class MultiTorqueGuard {
public:
    static constexpr int kMaxDrives = 4;
    using DriveLookup = std::function<MultiTorqueDrive(int id)>;

    /// `torques`: one torque request per drive (built for it: build::torque). `onBus`: the IDs
    /// known to be on the bus (answered or declared). The frame has a slot for each of IDs
    /// 1..4 and a drive in Broadcast Mode takes an empty slot as 0 A (a held axis drops its
    /// load), so a known drive of ID 1..4 must be named, with 0 if zero torque is meant.
    static MultiTorqueVerdict check(const QVector<protocol::Request> &torques, protocol::Link link,
                                    const DriveLookup &drive, const QSet<int> &onBus);
    /// The refusal in English, naming the drive and the limit (the engine's reason; lkctl and
    /// the GUI may word a Limit refusal with lktext's VerdictText instead).
    static QString text(const MultiTorqueVerdict &verdict);
};

} // namespace lk::safety
