#pragma once

#include "LiveCommand.h"

#include <bus/ScanTypes.h>

namespace lk::lkctl {

/// `lkctl scan`: find the drives on a bus (IDs 1..32 or a range, optionally every baud).
class ScanCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("scan"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// --from, --to and --retries into `o`; false after a usage error.
    bool readRange(const ArgParser &parser, bus::ScanOptions &o, Console &console,
                   int *status) const;
};

} // namespace lk::lkctl
