#pragma once

#include "WireMonitor.h"

#include <QtCore/QString>

namespace lk::app {

/// lksim's counters as a small JSON file that tests and benchmarks read (`--stats-file`):
/// {"requests":N,"replies":N,"collisions":N,"collisions_before_reply":N,
///  "collisions_during_reply":N,"overlaps_unjudged":N,"longest_request_gap_ms":X,
///  "request_gaps_over_100ms":N,"bad_checksum_replies":N,"running":BOOL}. Written whole (a
/// reader never sees half of it) at start, after every collision, on SIGUSR1 and at exit
/// ("running": false).
class StatsFile {
public:
    explicit StatsFile(QString path) : m_path(std::move(path)) {}
    bool isEnabled() const { return !m_path.isEmpty(); }
    /// False with errorString() set when the file cannot be written.
    /// `badChecksumReplies`: 0xA4 replies sent with fw 2.35's bad data checksum.
    bool write(const WireCounters &counters, qint64 badChecksumReplies, bool running);
    QString errorString() const { return m_error; }

private:
    QString m_path;
    QString m_error;
};

} // namespace lk::app
