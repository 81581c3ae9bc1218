#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QTemporaryDir>

#include <optional>

namespace lk::e2e {

/// lksim's counters (its --stats-file), summed over the processes one LksimProcess started.
struct LksimCounters {
    qint64 requests = 0;
    qint64 replies = 0;
    qint64 collisions = 0;          ///< requests that arrived while a reply was due or on the wire
    qint64 overlapsUnjudged = 0;    ///< overlaps within how late lksim may have read a request
    double longestRequestGapMs = 0; ///< the longest silence between two host requests
    qint64 requestGapsOver100ms = 0;
    qint64 badChecksumReplies = 0; ///< 0xA4 replies spoilt by --bad-checksum-pct
};

/// One lksim process serving a simulated bus on a pseudo-terminal, for end-to-end tests and
/// benchmarks: started with its arguments, it prints the device path as its first line.
/// Every lksim it starts keeps its counters in a stats file of its own (--stats-file).
class LksimProcess {
public:
    explicit LksimProcess(QString executable);
    ~LksimProcess(); ///< stop()

    /// Start `lksim ARGS` and wait (generously) for the device path. False on failure, with
    /// the reason in errorString().
    bool start(const QStringList &args);
    /// SIGTERM, then SIGKILL if it does not end within 5 s.
    void stop();
    /// SIGKILL: the "adapter" vanishes without a goodbye.
    void kill();
    bool isRunning() const { return m_process.state() != QProcess::NotRunning; }

    QString devicePath() const { return m_device; }
    QString errorString() const { return m_error; }
    /// Everything lksim wrote on standard error so far (its --verbose frame log).
    QByteArray log();
    /// Frames lksim received, cut from its --verbose log of pty reads ("<- " lines, which may
    /// hold several frames or part of one): each as upper-case hex with spaces.
    QList<QByteArray> receivedFrames();
    /// The counters of every lksim started so far, the running one included (its collision
    /// count is always current, the other counters as of its last write: ask after stop()).
    /// nullopt when a stats file could not be read: lksim wrote none, or it was unreadable.
    std::optional<LksimCounters> counters() const;
    /// counters() with the running lksim's counters current: it is asked to rewrite its stats
    /// file (SIGUSR1) and given up to a second to do so.
    std::optional<LksimCounters> currentCounters();

private:
    QString m_executable;
    QProcess m_process;
    QString m_device;
    QString m_error;
    QByteArray m_log;
    QTemporaryDir m_statsDir;
    int m_started = 0;        ///< lksim processes started (names their stats files)
    QStringList m_statsFiles; ///< of those that started serving
};

} // namespace lk::e2e
