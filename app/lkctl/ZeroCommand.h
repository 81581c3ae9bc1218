#pragma once

#include "LiveCommand.h"

#include <protocol/Command.h>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// The zero tools of the Encoder view on the command line, each confirmed with --yes, sent
/// once and checked by reading the drive back:
/// - `lkctl zero ID --ram --yes`: clear_angle (0x95), the present position becomes angle 0
///   until power-off; read_multi_turn (0x92) before and after tells whether it took;
/// - `lkctl zero ID --rom --yes`: write_zero_rom (0x19), the present position becomes the
///   zero in flash, from the next power-on; never repeated, a lost reply is said as such;
/// - `lkctl clear-turns ID --yes`: clear_turn_count (0x93, V2.35 only), the multi-turn angle
///   keeps the angle within the present turn; checked with read_multi_turn.
class ZeroCommand : public LiveCommand {
public:
    enum class Kind { Zero, ClearTurns };
    explicit ZeroCommand(Kind kind) : m_kind(kind) {}

    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

    /// How close to 0 (rotor degrees) a cleared angle reads, as the Encoder view judges it.
    static constexpr double kZeroToleranceDeg = 1.0;

private:
    struct Plan {
        int id = 0;
        bool rom = false;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    int refuseWithoutYes(Console &console, const Plan &plan) const;
    /// read_multi_turn; nullopt after printing why.
    static std::optional<double> multiTurnDeg(LiveBus &bus, int id);
    struct Angles {
        double before = 0, after = 0; ///< multi-turn, rotor degrees
    };
    /// read_multi_turn, `command` sent once, read_multi_turn; nullopt after printing why
    /// (and whether the command may have been applied).
    static std::optional<Angles> sendBetweenAngles(LiveBus &bus, int id, protocol::Command command);
    int clearAngle(LiveBus &bus, const Plan &plan) const;
    int writeZeroRom(LiveBus &bus, const Plan &plan) const;
    int clearTurns(LiveBus &bus, const Plan &plan, double gearRatio) const;
    /// The result line (JSON or text) of a command checked by the angle before and after.
    void printAngles(LiveBus &bus, const Plan &plan, protocol::Command sent, double before,
                     double after, const QString &verdict) const;

    Kind m_kind;
};

} // namespace lk::lkctl
