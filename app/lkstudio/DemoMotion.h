#pragma once

#include <bus/RequestResult.h>

#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QVector>

class QTimer;

namespace lk::ui {
class BusController;
struct ConnectionChoice;
struct StartupOptions;
} // namespace lk::ui

/// Makes the drives of the built-in simulated bus move (speed steps every two seconds) so
/// that a first run, a demo or a documentation screenshot shows live plots. The first steps
/// go out as soon as the scan has found the drives. It sends only on the simulator, through
/// the normal bus path, and stops for good when the user takes over: at the first command
/// that moves, switches or stops a drive and is not its own (it then sets the other drives it
/// moved back to 0 dps), at the first emergency stop or stop from the emergency lane (quitting,
/// the speed watch: every drive is being stopped, none is set to 0 dps), or when the link
/// leaves the simulator.
class DemoMotion : public QObject {
    Q_OBJECT
public:
    static constexpr int kStepMs = 2000;

    explicit DemoMotion(lk::ui::BusController *controller, int stepMs = kStepMs,
                        QObject *parent = nullptr);
    void start();
    bool isRunning() const { return m_running; }
    /// lkstudio moves the simulated drives at start when it opens the built-in bus without
    /// having been told which bus (a first run, or the adapter is not plugged in), and with
    /// --sim-motion. `--sim SPEC` (tests, chosen drives) stays still.
    static bool startsOnItsOwn(const lk::ui::StartupOptions &options,
                               const lk::ui::ConnectionChoice &choice);

signals:
    void started();
    /// The demo stopped for good (the user took over, an emergency stop, another link).
    void stopped();

private:
    void step();
    void observe(const lk::bus::RequestResult &result);
    /// Someone else's command, as soon as it is queued (observe() sees its completion: by
    /// then a step of the demo could already have been queued behind it).
    void takeOver(int id, lk::protocol::Command command, lk::bus::Priority priority);
    void stopForGood();
    /// Speed 0 to every drive the demo set moving but `except`.
    void standStill(int except);
    bool canMove() const;

    lk::ui::BusController *m_controller;
    QTimer *m_timer;
    QSet<quint64> m_tickets; ///< the demo's own commands not completed yet
    QSet<int> m_moved;       ///< drives the demo has set moving
    int m_phase = 0;
    bool m_running = false;
    bool m_stopped = false;
    bool m_sending = false; ///< inside the demo's own send(): its submission is not a take-over
};
