#pragma once

#include "DriveParams.h"

#include <protocol/Request.h>

#include <QtCore/QStringList>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// `lkctl write ID param NAME VALUE... --ram|--rom`: one V2.35 parameter (max_angle_deg as
/// the pair 0x9B then 0x9C), each request sent once, then read back with read_param.
class ParamWrite {
public:
    /// What to send, decided (and range-checked) before the bus is touched.
    struct Plan {
        int id = 0;
        DriveParam param;
        bool rom = false;
        bool json = false;
        QList<protocol::Request> requests;       ///< write_param_ram/rom, in order
        QList<protocol::ParameterValue> written; ///< their values, one per request
        QString command() const;                 ///< "write_param_ram" or "write_param_rom"
    };
    /// From the positionals `ID param NAME VALUE...`; nullopt with `error` (exit 2).
    static std::optional<Plan> plan(const QStringList &pos, bool rom, bool json, QString *error);
    /// Send, read back, print; the exit status (kExitMismatch when the drive holds other values,
    /// kExitFailure when it reported failure or did not answer).
    static int run(LiveBus &bus, const Plan &plan);

private:
    static int readBack(LiveBus &bus, const Plan &plan);
};

} // namespace lk::lkctl
