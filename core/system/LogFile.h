#pragma once

#include <QtCore/QFile>
#include <QtCore/QMutex>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QtGlobal>

namespace lk::system {

/// A program's log: every Qt message goes to a file (rotated by size, a few generations kept)
/// and still to stderr, and the latest warnings are kept in memory for a bug report. One log
/// can be installed as the process's message handler at a time.
class LogFile {
public:
    static constexpr qint64 kDefaultMaxBytes = 1024 * 1024;
    static constexpr int kDefaultGenerations = 3; ///< lkstudio.log.1 ... .3 besides the log
    static constexpr int kRecentProblems = 20;

    /// `$XDG_STATE_HOME/<app>/<app>.log`, or `~/.local/state/<app>/<app>.log` when
    /// XDG_STATE_HOME is unset or not absolute (the XDG base directory rule).
    static QString defaultPath(const QString &appName);

    explicit LogFile(const QString &path, qint64 maxBytes = kDefaultMaxBytes,
                     int generations = kDefaultGenerations);
    ~LogFile(); ///< uninstalls itself when installed
    LogFile(const LogFile &) = delete;
    LogFile &operator=(const LogFile &) = delete;

    /// Create the folder, rotate a log already past the size, open for appending.
    bool open(QString *error = nullptr);
    QString path() const { return m_path; }

    /// Become the Qt message handler; the previous one (stderr) still gets every message.
    void install();
    void uninstall();
    /// The installed log, or null.
    static LogFile *installed();

    /// Append one message (thread-safe; any thread may log).
    void write(QtMsgType type, const QMessageLogContext &context, const QString &message);
    /// The latest warnings and errors, oldest first, each with its time.
    QStringList recentProblems() const;

    /// log.N-1 -> log.N ... log -> log.1; the oldest beyond `generations` is dropped.
    static void rotate(const QString &path, int generations);

private:
    static void handler(QtMsgType type, const QMessageLogContext &context, const QString &message);
    bool reopen(QString *error);

    QString m_path;
    qint64 m_maxBytes;
    int m_generations;
    mutable QMutex m_mutex;
    QFile m_file;
    QStringList m_recent;
    QtMessageHandler m_previous = nullptr;
};

} // namespace lk::system
