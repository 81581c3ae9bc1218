#pragma once

#include "Subcommand.h"

namespace lk::lkctl {

/// `lkctl replay FILE [--csv | --json]`: a recording decoded as `lkctl listen` decodes a live
/// bus, through the same passive path (bus::ListenMonitor: pairing by order, the reply intake,
/// the other master's commanded values), on the recording's own clock and with its recorded
/// decode context. Rows as `lkctl listen` prints them; what the master did on standard error.
class ReplayCommand : public Subcommand {
public:
    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;
};

} // namespace lk::lkctl
