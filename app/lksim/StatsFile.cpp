#include "StatsFile.h"

#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace lk::app {

bool StatsFile::write(const WireCounters &counters, qint64 badChecksumReplies, bool running)
{
    if (!isEnabled())
        return true;
    const QJsonObject o{{QStringLiteral("requests"), counters.requests},
                        {QStringLiteral("replies"), counters.replies},
                        {QStringLiteral("collisions"), counters.collisions()},
                        {QStringLiteral("collisions_before_reply"), counters.collisionsBefore},
                        {QStringLiteral("collisions_during_reply"), counters.collisionsDuring},
                        {QStringLiteral("overlaps_unjudged"), counters.overlapsUnjudged},
                        {QStringLiteral("longest_request_gap_ms"),
                         std::round(counters.longestRequestGapS * 1e4) / 10},
                        {QStringLiteral("request_gaps_over_100ms"), counters.requestGapsOver100ms},
                        {QStringLiteral("bad_checksum_replies"), badChecksumReplies},
                        {QStringLiteral("running"), running}};
    // A temporary file renamed over the old one: a reader sees the old or the new counters,
    // never half a file. No fsync: it is written after every collision, mid-traffic.
    const QString temp = m_path + QStringLiteral(".tmp");
    QFile f(temp);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        f.write(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n') < 0) {
        m_error = QStringLiteral("%1: %2").arg(temp, f.errorString());
        return false;
    }
    f.close();
    if (std::rename(QFile::encodeName(temp).constData(), QFile::encodeName(m_path).constData())) {
        m_error = QStringLiteral("%1: %2").arg(m_path, QString::fromLocal8Bit(strerror(errno)));
        return false;
    }
    return true;
}

} // namespace lk::app
