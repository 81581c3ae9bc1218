#pragma once

#include <sim/ControllerTransaction.h>

#include <QtCore/QFile>
#include <QtCore/QList>
#include <QtCore/QString>

#include <array>

namespace lk::app {

/// lksim --controller-log: each finished request of the foreign master as one JSON line
/// (ControllerTransaction::toJsonLine), flushed per batch so that a test reads it while lksim
/// runs; and the count of each outcome, for the exit summary. No path: counts only.
class ControllerLogFile {
public:
    explicit ControllerLogFile(QString path) : m_path(std::move(path)), m_file(m_path) {}

    /// Opens (truncates) the file; false after saying why on standard error.
    bool open();
    /// Counts and writes `done`. A write error is said once and ends the log (not the counts).
    void record(const QList<sim::ControllerTransaction> &done);
    qint64 count(sim::ControllerTransaction::Outcome outcome) const
    {
        return m_outcomes[static_cast<size_t>(outcome)];
    }
    qint64 total() const;
    /// "N requests (N answered, N unanswered, N dropped, N garbled, N collided)".
    QString outcomesText() const;

private:
    QString m_path;
    QFile m_file;
    std::array<qint64, 5> m_outcomes{};
};

} // namespace lk::app
