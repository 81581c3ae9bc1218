#include "LksimProcess.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QThread>

#include <algorithm>

#include <signal.h>

namespace lk::e2e {

namespace {
constexpr int kStartTimeoutMs = 30000; // a loaded 2-core machine may be slow to exec
constexpr int kStopTimeoutMs = 5000;
} // namespace

LksimProcess::LksimProcess(QString executable) : m_executable(std::move(executable)) {}

LksimProcess::~LksimProcess()
{
    stop();
}

bool LksimProcess::start(const QStringList &args)
{
    stop();
    m_device.clear();
    m_error.clear();
    m_log.clear();
    m_process.setProgram(m_executable);
    const QString stats = m_statsDir.filePath(QStringLiteral("lksim-%1.json").arg(++m_started));
    m_process.setArguments(args + QStringList{QStringLiteral("--stats-file"), stats});
    m_process.start();
    if (!m_process.waitForStarted(kStartTimeoutMs)) {
        m_error = QStringLiteral("cannot start %1: %2").arg(m_executable, m_process.errorString());
        return false;
    }
    const QDeadlineTimer deadline(kStartTimeoutMs);
    while (!m_process.canReadLine() && !deadline.hasExpired() &&
           m_process.state() == QProcess::Running)
        m_process.waitForReadyRead(int(std::max<qint64>(1, deadline.remainingTime())));
    m_device = QString::fromLocal8Bit(m_process.readLine()).trimmed();
    if (m_device.isEmpty()) {
        m_error = QStringLiteral("lksim printed no device path: %1")
                      .arg(QString::fromLocal8Bit(m_process.readAllStandardError()));
        stop();
        return false;
    }
    m_statsFiles.append(stats); // lksim wrote it before it printed the path
    return true;
}

void LksimProcess::stop()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.terminate();
    if (!m_process.waitForFinished(kStopTimeoutMs)) {
        m_process.kill();
        m_process.waitForFinished(kStopTimeoutMs);
    }
    m_log += m_process.readAllStandardError();
}

void LksimProcess::kill()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.kill();
    m_process.waitForFinished(kStopTimeoutMs);
    m_log += m_process.readAllStandardError();
}

QByteArray LksimProcess::log()
{
    if (m_process.state() != QProcess::NotRunning) {
        // Pull what lksim wrote into the pipe meanwhile: without an event loop in between,
        // QProcess has not read it yet.
        m_process.setReadChannel(QProcess::StandardError);
        while (m_process.waitForReadyRead(50)) {
        }
        m_log += m_process.readAllStandardError();
    }
    return m_log;
}

QList<QByteArray> LksimProcess::receivedFrames()
{
    // lksim logs each read of the pty ("<- 3E 80 02 ..."), and a read of a loaded lksim can
    // hold two frames (a motor_off to a silent ID and the next one) or part of one: cut the
    // byte stream into frames by their header (0x3E, command, ID, length, checksum, then the
    // data and its checksum when length > 0), skipping a byte that cannot start one.
    QByteArray stream;
    for (const QByteArray &line : log().split('\n')) {
        if (line.startsWith("<- "))
            stream += QByteArray::fromHex(line.mid(3).trimmed());
    }
    QList<QByteArray> frames;
    qsizetype at = 0;
    while (stream.size() - at >= 5) {
        if (quint8(stream.at(at)) != 0x3E) {
            ++at;
            continue;
        }
        const int length = quint8(stream.at(at + 3));
        const qsizetype size = 5 + (length > 0 ? length + 1 : 0);
        if (stream.size() - at < size)
            break; // the rest has not been read yet
        frames.append(stream.mid(at, size).toHex(' ').toUpper());
        at += size;
    }
    return frames;
}

std::optional<LksimCounters> LksimProcess::currentCounters()
{
    if (m_process.state() == QProcess::Running && !m_statsFiles.isEmpty()) {
        QFile file(m_statsFiles.last());
        const QByteArray before = file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
        file.close();
        ::kill(static_cast<pid_t>(m_process.processId()), SIGUSR1);
        // Rewritten whole by a rename: a changed content is the new file. An idle bus may
        // write the same counters again; then the old ones are current anyway.
        QDeadlineTimer deadline(1000);
        while (!deadline.hasExpired()) {
            QThread::msleep(10);
            if (file.open(QIODevice::ReadOnly)) {
                const QByteArray now = file.readAll();
                file.close();
                if (now != before)
                    break;
            }
        }
    }
    return counters();
}

std::optional<LksimCounters> LksimProcess::counters() const
{
    if (!m_statsDir.isValid())
        return std::nullopt;
    LksimCounters sum;
    for (const QString &path : m_statsFiles) {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return std::nullopt;
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        if (!o.contains(QStringLiteral("collisions")))
            return std::nullopt;
        sum.requests += o.value(QStringLiteral("requests")).toInteger();
        sum.replies += o.value(QStringLiteral("replies")).toInteger();
        sum.collisions += o.value(QStringLiteral("collisions")).toInteger();
        sum.overlapsUnjudged += o.value(QStringLiteral("overlaps_unjudged")).toInteger();
        sum.longestRequestGapMs = std::max(
            sum.longestRequestGapMs, o.value(QStringLiteral("longest_request_gap_ms")).toDouble());
        sum.requestGapsOver100ms += o.value(QStringLiteral("request_gaps_over_100ms")).toInteger();
        sum.badChecksumReplies += o.value(QStringLiteral("bad_checksum_replies")).toInteger();
    }
    return sum;
}

} // namespace lk::e2e
