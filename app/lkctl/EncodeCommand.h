#pragma once

#include "Subcommand.h"

namespace lk::lkctl {

/// `lkctl encode NAME --id N [--FIELD VALUE ...]`: prints a request frame as hex (CLI.md).
class EncodeCommand : public Subcommand {
public:
    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    static QString commandList();
};

} // namespace lk::lkctl
