#pragma once

#include "LiveCommand.h"

#include <protocol/Command.h>
#include <protocol/Request.h>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// `lkctl write ID pid ... --ram|--rom [--yes]`, `lkctl write ID accel DPS2 --ram` and
/// `lkctl write ID param NAME VALUE... --ram|--rom [--yes]` (V2.35): write, read back, print
/// what the drive now holds; a read-back that differs fails loudly.
class WriteCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("write"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// What to write, decided from the arguments before the bus is touched.
    struct Plan {
        protocol::Request request;
        QString command; ///< "write_pid_ram", ...
        protocol::Command readBack = protocol::Command::ReadPid;
        bool rom = false;
        bool json = false;
        QString what; ///< "PID gains", "acceleration"
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    /// `write ID param NAME VALUE...` (V2.35), see ParamWrite.
    int runParam(const ArgParser &parser, const BusOptions &busOptions, Console &console) const;
    /// `write ID pid ...` to a drive --drives declares CAN V2.36: 0xC1, RAM only
    /// (ControlParamWrite); --rom refused, nothing sent.
    int runCan236Pid(const ArgParser &parser, const BusOptions &busOptions, Console &console) const;
    /// `write ID param NAME VALUE...` on CAN: V2.36's control parameters (0xC1, RAM only).
    int runCanParam(const ArgParser &parser, const BusOptions &busOptions, Console &console,
                    bool rom) const;
    /// --rom (true) or --ram (false); nullopt with `error` when neither or both are given.
    static std::optional<bool> romChosen(const ArgParser &parser, QString *error);
    /// A ROM write without --yes: explain, send nothing, kExitRefused.
    int refuseRom(Console &console, const QString &what) const;
    /// Read back what was written, print it; kExitMismatch when it differs. `acknowledged`:
    /// the write's reply arrived (else the read-back answers whether it took effect).
    int readBack(LiveBus &bus, const Plan &plan, bool acknowledged);
    /// read_model first: whether drive `id` speaks `generation`; if not, prints `otherwise`
    /// (or why the model could not be read) and nothing more is sent.
    static bool speaks(LiveBus &bus, int id, protocol::Generation generation,
                       const QString &otherwise);
};

} // namespace lk::lkctl
