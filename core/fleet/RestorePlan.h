#pragma once

#include "DriveSnapshot.h"

#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::fleet {

/// Why a target is not written: `key` names what differs or is wrong ("link", "generation",
/// "series", "angle_kp", "read", "rom"), `reason` says it in English.
struct Refusal {
    QString key;
    QString reason;
};

/// One value a restore changes on its target.
struct ParamChange {
    QString key;
    qint64 from = 0; ///< what the target held (always read: a target not read is refused)
    qint64 to = 0;
};

/// What restoring `source` onto `target` would do, decided before anything is sent: refused
/// (the reason), or the exact values that change.
struct RestorePlan {
    DriveSnapshot source;
    DriveSnapshot target; ///< as read just before; the undo of this restore
    std::optional<Refusal> refusal;
    QVector<ParamChange> changes; ///< restorable keys whose value differs, catalogue order

    int targetId() const { return target.id(); }
    QStringList changedKeys() const;

    /// Refused when the source or the target was not read completely, when link, generation
    /// or series differ (or a series is not known; on CAN the target's are the user's word),
    /// or when a value is outside the target's range; otherwise the changes.
    static RestorePlan make(const DriveSnapshot &source, const DriveSnapshot &target);
};

} // namespace lk::fleet
