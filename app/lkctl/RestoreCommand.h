#pragma once

#include "LiveCommand.h"

#include <fleet/FleetRestore.h>

namespace lk::lkctl {

class LiveBus;

/// `lkctl restore FILE ...` (a backup onto drives) and `lkctl clone FROM TO...` (one drive's
/// values onto others): targets read first (kept as an undo file), the diff printed, refused
/// as a whole when any target is refused, RAM written and read back, ROM only with --rom --yes.
class RestoreCommand : public LiveCommand {
public:
    enum class Kind { Restore, Clone };
    explicit RestoreCommand(Kind kind) : m_kind(kind) {}

    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// The restores of `restore FILE [IDS] [--map]`; nullopt after printing why (exit 2).
    std::optional<QVector<fleet::FleetRestore::Job>> restoreJobs(const ArgParser &parser,
                                                                 Console &console) const;
    /// --rom onto a CAN V2.36 drive `id`: says it is RAM only, nothing sent; kExitRefused.
    int refuseRamOnly(Console &console, int id) const;
    /// Prepares, writes the undo file, refuses or executes, prints; returns the exit status.
    int restore(LiveBus &bus, const QVector<fleet::FleetRestore::Job> &jobs, bool rom,
                const QString &undoPath, bool json) const;

    Kind m_kind;
};

} // namespace lk::lkctl
