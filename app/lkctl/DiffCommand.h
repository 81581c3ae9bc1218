#pragma once

#include "LiveCommand.h"

#include <fleet/DriveSnapshot.h>

namespace lk::lkctl {

/// `lkctl diff FILE [--map A:B]` (a backup against the drives) and `lkctl diff ID ID...`
/// (drives against the first).
class DiffCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("diff"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// Prints the comparisons and returns the exit status (0 all equal, 5 some differ, 1 a
    /// drive could not be read).
    int report(Console &console, bool json,
               const QVector<QPair<fleet::DriveSnapshot, fleet::DriveSnapshot>> &pairs) const;
};

} // namespace lk::lkctl
