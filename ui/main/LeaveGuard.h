#pragma once

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <functional>

class QWidget;

namespace lk::ui {

class BusController;
class CommandedMotion;

/// Nothing lkstudio set moving is left turning unasked when it quits or disconnects. Before
/// the window closes (Ctrl+Q, the close button, a termination signal, logout) and before the
/// bus is disconnected, the drives commanded to move on this connection (CommandedMotion) are
/// stopped: the user is asked "Stop drives 1, 4 before quitting?" with Stop as the default,
/// or may leave them running (logged) or stay. A termination signal stops them without
/// asking. The stop is Motor Off (0x80) to each of those drives from the emergency lane;
/// leaving waits (at most kStopWaitMs) for their acknowledgements and the log (and, on a
/// disconnect, the banner) says which drives acknowledged and which may still be moving.
/// Drives moved only by the first-run demo on the built-in simulated bus are stopped without
/// asking: they exist only inside lkstudio (docs/SUPERVISION.md).
class LeaveGuard : public QObject {
    Q_OBJECT
public:
    enum class Leaving {
        Quit,       ///< the window closes: ask
        Disconnect, ///< the bus is closed, or replaced by another: ask
        Signal,     ///< SIGTERM, SIGINT, a logout without interaction: stop without asking
    };
    enum class Choice { Stop, LeaveRunning, Stay };
    static constexpr int kStopWaitMs = 3000;

    /// None of the arguments is owned; `dialogParent` parents the question.
    LeaveGuard(BusController *controller, CommandedMotion *motion, QWidget *dialogParent,
               QObject *parent = nullptr);

    /// The demo is moving the simulated drives (its drives are the only ones commanded).
    void setDemoRunning(bool running) { m_demo = running; }
    /// Whether leaving goes on; when drives were commanded to move, asks (per `why`), stops
    /// them and waits for their acknowledgements first. Returns at once when none were.
    bool prepare(Leaving why);
    /// What the last stop verified (also logged), or why they were left running.
    QString lastReport() const { return m_report; }

    /// "1, 4"
    static QString idList(const QVector<int> &ids);

signals:
    /// A stop before disconnecting ended: `text` says what it verified (for the banner);
    /// `allAcknowledged` false when a drive may still be moving.
    void stopReported(const QString &text, bool allAcknowledged);

private:
    Choice ask(Leaving why, const QVector<int> &ids) const;
    /// Motor Off to `ids`, waiting for every end (bounded); returns the acknowledged ones.
    QVector<int> stopAndWait(const QVector<int> &ids);
    void report(const QVector<int> &ids, const QVector<int> &acknowledged, bool demo);

    BusController *m_controller;
    CommandedMotion *m_motion;
    QWidget *m_dialogParent;
    bool m_demo = false;
    QString m_report;
};

} // namespace lk::ui
