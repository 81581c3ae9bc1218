#pragma once

#include "ConfirmDialog.h"

#include <protocol/Values.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>
#include <QtCore/QTime>

#include <optional>

namespace lk::ui {

/// What a tuning write sent, to compare with the read-back that follows it.
struct TuningWrite {
    bool rom = false;
    std::optional<protocol::PidGains> pid;
    std::optional<qint32> accelDps2; ///< only when acceleration was written too
};

/// The tuning view's questions and verdicts, worded once: what a write will do before it is
/// sent, and what its read-back proved (and, for ROM on V2.3, what it cannot prove).
class TuningText {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::TuningText)
public:
    /// "1/2, 3/4, 5/6": angle, speed, iq Kp/Ki.
    static QString gains(const protocol::PidGains &p);
    /// "12:03:15".
    static QString time(const QTime &t);
    static ConfirmRequest romWrite(int id, const protocol::PidGains &pid);
    /// `values`: the values to restore, worded by the drive's parameter set.
    static ConfirmRequest restore(int id, const QTime &readAt, const QString &values);
    /// Where the read-back differs from what was sent, or did not complete; empty when the
    /// drive holds what was sent.
    static QStringList readBackProblems(const TuningWrite &sent,
                                        const std::optional<protocol::PidGains> &pid,
                                        const std::optional<qint32> &accelDps2, bool complete);
    /// The status after a write whose read-back showed what was sent.
    static QString written(const TuningWrite &sent, int id);
    /// Why a CAN V2.36 drive's view has no ROM button: its control parameters live in RAM.
    static QString can236RamOnly();
};

} // namespace lk::ui
