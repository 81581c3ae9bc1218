#pragma once

#include "Subcommand.h"

namespace lk::lkctl {

/// `lkctl export FILE --pcap OUT | --csv OUT`: a recording as a pcap file for Wireshark (with
/// packaging/wireshark/lkservo.lua), or its telemetry as CSV (docs/CSV.md, long layout).
class ExportCommand : public Subcommand {
public:
    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    int exportPcap(const QString &in, const QString &out, Console &console);
    int exportCsv(const QString &in, const QString &out, Console &console);
};

} // namespace lk::lkctl
