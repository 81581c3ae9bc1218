#include "ControllerLogFile.h"

#include <cstdio>
#include <numeric>

namespace lk::app {

using Outcome = sim::ControllerTransaction::Outcome;

bool ControllerLogFile::open()
{
    if (m_path.isEmpty() || m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return true;
    std::fprintf(stderr, "lksim: --controller-log %s: %s\n", qPrintable(m_path),
                 qPrintable(m_file.errorString()));
    return false;
}

void ControllerLogFile::record(const QList<sim::ControllerTransaction> &done)
{
    if (done.isEmpty())
        return;
    QByteArray lines;
    for (const sim::ControllerTransaction &t : done) {
        ++m_outcomes[static_cast<size_t>(t.outcome)];
        if (m_file.isOpen())
            lines += t.toJsonLine() + '\n';
    }
    if (m_file.isOpen() && (m_file.write(lines) != lines.size() || !m_file.flush())) {
        std::fprintf(stderr, "lksim: --controller-log %s: %s; the log stops here\n",
                     qPrintable(m_path), qPrintable(m_file.errorString()));
        m_file.close();
    }
}

qint64 ControllerLogFile::total() const
{
    return std::accumulate(m_outcomes.begin(), m_outcomes.end(), qint64(0));
}

QString ControllerLogFile::outcomesText() const
{
    return QStringLiteral("%1 requests (%2 answered, %3 unanswered, %4 dropped, %5 garbled, %6 "
                          "collided)")
        .arg(total())
        .arg(count(Outcome::Answered))
        .arg(count(Outcome::Unanswered))
        .arg(count(Outcome::Dropped))
        .arg(count(Outcome::Garbled))
        .arg(count(Outcome::Collided));
}

} // namespace lk::app
