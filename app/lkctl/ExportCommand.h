#pragma once

#include "Subcommand.h"

class QIODevice;

namespace lk::recording {
class RecordingReader;
}

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
    /// Write the reader's recording to `out`; what was written ("12 packets").
    static QString writePcap(recording::RecordingReader &reader, QIODevice &out);
    static QString writeCsv(recording::RecordingReader &reader, QIODevice &out);
};

} // namespace lk::lkctl
