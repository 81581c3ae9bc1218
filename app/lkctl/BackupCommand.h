#pragma once

#include "LiveCommand.h"

namespace lk::lkctl {

/// `lkctl backup [IDS|all] --out FILE`: every parameter of several drives into one file.
class BackupCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("backup"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;
};

} // namespace lk::lkctl
