#include "LogFile.h"

#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QMutexLocker>

#include <atomic>
#include <cstdio>

namespace lk::system {

namespace {
std::atomic<LogFile *> g_installed{nullptr};

const char *typeName(QtMsgType type)
{
    switch (type) {
    case QtDebugMsg:
        return "debug";
    case QtInfoMsg:
        return "info";
    case QtWarningMsg:
        return "warning";
    case QtCriticalMsg:
        return "critical";
    case QtFatalMsg:
        return "fatal";
    }
    return "?";
}

QString generation(const QString &path, int n)
{
    return QStringLiteral("%1.%2").arg(path).arg(n);
}
} // namespace

QString LogFile::defaultPath(const QString &appName)
{
    // Qt 6.4 has no QStandardPaths::StateLocation (6.7): follow the XDG rule by hand.
    QString state = qEnvironmentVariable("XDG_STATE_HOME");
    if (state.isEmpty() || !QDir::isAbsolutePath(state))
        state = QDir::homePath() + QStringLiteral("/.local/state");
    return QStringLiteral("%1/%2/%2.log").arg(state, appName);
}

LogFile::LogFile(const QString &path, qint64 maxBytes, int generations)
    : m_path(path), m_maxBytes(qMax<qint64>(1, maxBytes)), m_generations(qMax(1, generations))
{
}

LogFile::~LogFile()
{
    uninstall();
}

bool LogFile::open(QString *error)
{
    QMutexLocker lock(&m_mutex);
    const QString dir = QFileInfo(m_path).absolutePath();
    if (!QDir().mkpath(dir)) {
        if (error)
            *error = QStringLiteral("cannot create %1").arg(dir);
        return false;
    }
    if (QFileInfo(m_path).size() >= m_maxBytes)
        rotate(m_path, m_generations);
    return reopen(error);
}

bool LogFile::reopen(QString *error)
{
    m_file.close();
    m_file.setFileName(m_path);
    if (m_file.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text))
        return true;
    if (error)
        *error = QStringLiteral("%1: %2").arg(m_path, m_file.errorString());
    return false;
}

void LogFile::rotate(const QString &path, int generations)
{
    QFile::remove(generation(path, generations));
    for (int n = generations - 1; n >= 1; --n)
        QFile::rename(generation(path, n), generation(path, n + 1));
    QFile::rename(path, generation(path, 1));
}

void LogFile::install()
{
    LogFile *expected = nullptr;
    if (!g_installed.compare_exchange_strong(expected, this))
        return; // another log is the handler; there is only one per process
    m_previous = qInstallMessageHandler(&LogFile::handler);
}

void LogFile::uninstall()
{
    LogFile *self = this;
    if (g_installed.compare_exchange_strong(self, nullptr))
        qInstallMessageHandler(m_previous);
}

LogFile *LogFile::installed()
{
    return g_installed.load();
}

void LogFile::handler(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    LogFile *log = g_installed.load();
    if (!log)
        return;
    if (log->m_previous) {
        log->m_previous(type, context, message);
    } else {
        const QString line = qFormatLogMessage(type, context, message);
        std::fprintf(stderr, "%s\n", qPrintable(line));
    }
    log->write(type, context, message);
}

void LogFile::write(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    const QString time = QDateTime::currentDateTime().toString(Qt::ISODateWithMs);
    const QString category = context.category && qstrcmp(context.category, "default") != 0
                                 ? QString::fromLatin1(context.category) + QStringLiteral(": ")
                                 : QString();
    const QString line =
        QStringLiteral("%1 %2 %3%4\n").arg(time, QLatin1String(typeName(type)), category, message);
    QMutexLocker lock(&m_mutex);
    if (type == QtWarningMsg || type == QtCriticalMsg || type == QtFatalMsg) {
        m_recent << line.trimmed();
        while (m_recent.size() > kRecentProblems)
            m_recent.removeFirst();
    }
    if (!m_file.isOpen())
        return;
    m_file.write(line.toUtf8());
    m_file.flush(); // a crash right after must not lose the line that explains it
    if (m_file.size() >= m_maxBytes) {
        m_file.close();
        rotate(m_path, m_generations);
        reopen(nullptr);
    }
}

QStringList LogFile::recentProblems() const
{
    QMutexLocker lock(&m_mutex);
    return m_recent;
}

} // namespace lk::system
