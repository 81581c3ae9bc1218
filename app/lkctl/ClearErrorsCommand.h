#pragma once

#include "LiveCommand.h"

namespace lk::lkctl {

/// `lkctl clear-errors ID`: clear_errors (0x9B) to one drive, after reading its flags
/// (read_state1) so that what was cleared is told; the reply carries the flags left, which
/// are still set when their cause is (exit 5).
class ClearErrorsCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("clear-errors"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;
};

} // namespace lk::lkctl
