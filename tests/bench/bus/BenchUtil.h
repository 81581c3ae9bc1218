#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QDeadlineTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QList>
#include <QtCore/QPair>
#include <QtCore/QString>
#include <QtCore/QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace lk::bench {

/// Run the event loop until `done` is true or `timeoutMs` pass; returns `done()`. Sleeps
/// between events: processEvents with a time limit would poll and keep a core busy, which on
/// a 2-core machine takes time from the bus thread and lksim being measured.
inline bool waitUntil(const std::function<bool()> &done, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    QTimer tick; // bounds each sleep, so that the deadline is seen
    tick.start(20);
    while (!done() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    return done();
}

/// Run the event loop for `ms` milliseconds.
inline void spin(int ms)
{
    waitUntil([] { return false; }, ms);
}

inline double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/// One JSON object on one line, keys in the order added; numbers rounded to `decimals`.
class JsonLine {
public:
    void add(const QString &key, double value, int decimals = 3)
    {
        QString text =
            std::isfinite(value) ? QString::number(value, 'f', decimals) : QStringLiteral("null");
        m_items.append({key, text});
    }
    void addInt(const QString &key, qint64 value) { m_items.append({key, QString::number(value)}); }
    void addText(const QString &key, const QString &value)
    {
        m_items.append({key, QLatin1Char('"') + value + QLatin1Char('"')});
    }
    /// `json` as it is (an array, say).
    void addRaw(const QString &key, const QString &json) { m_items.append({key, json}); }
    void print() const
    {
        QString line = QStringLiteral("{");
        for (qsizetype i = 0; i < m_items.size(); ++i) {
            if (i > 0)
                line += QLatin1Char(',');
            line += QStringLiteral("\"%1\":%2").arg(m_items.at(i).first, m_items.at(i).second);
        }
        line += QLatin1Char('}');
        std::printf("%s\n", qPrintable(line));
        std::fflush(stdout);
    }

private:
    QList<QPair<QString, QString>> m_items;
};

} // namespace lk::bench
