#pragma once

#include <protocol/ControlParameter.h>

#include <QtCore/QList>
#include <QtCore/QStringList>

#include <array>
#include <optional>

namespace lk::lkctl {

class LiveBus;

/// `lkctl write ID pid ...` and `lkctl write ID param NAME VALUE...` on a CAN V2.36 drive: its
/// gains and input limits are control parameters (docs/CAN.md 4.1), written with 0xC1 to RAM,
/// the only place they live, each sent once and read back with 0xC0. `pid` gives six gains
/// (Kp, Ki of each loop) where the drive keeps three (Kp, Ki, Kd): each loop's Kd is read
/// first and written back as read, never guessed.
class ControlParamWrite {
public:
    struct Plan {
        int id = 0;
        bool json = false;
        QString param;                            ///< NAME; empty for `pid`
        QList<protocol::ControlParamId> ids;      ///< what is written, in order
        QList<protocol::ControlParameter> values; ///< param: built before the bus is touched
        std::array<quint16, 6> gains{};           ///< pid: angle Kp Ki, speed Kp Ki, iq Kp Ki
        bool isPid() const { return param.isEmpty(); }
    };
    /// `write ID pid G1..G6` on V2.36: gains 0..65535; nullopt with `error` (exit 2).
    static std::optional<Plan> pidPlan(int id, const QStringList &gains, bool json, QString *error);
    /// `write ID param NAME VALUE...` on V2.36 (names of names()); nullopt with `error`.
    static std::optional<Plan> paramPlan(const QStringList &pos, bool json, QString *error);
    /// "angle_pid, speed_pid, iq_pid, max_torque, max_speed_dps, ...": the control parameters
    /// by the names `write ID param` takes on CAN V2.36.
    static QString names();
    /// Read what is needed, write, read back, print; the exit status (kExitMismatch when the
    /// drive holds other values, kExitFailure when it did not answer).
    static int run(LiveBus &bus, Plan plan);
    /// Why `--rom` is refused on CAN V2.36 (nothing is sent).
    static QString romRefusal(int id);

private:
    /// 0xC0 of `param`; nullopt after printing why.
    static std::optional<protocol::ControlParameter> read(LiveBus &bus, int id,
                                                          protocol::ControlParamId param);
    static int readBack(LiveBus &bus, const Plan &plan);
};

} // namespace lk::lkctl
