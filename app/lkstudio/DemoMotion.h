#pragma once

#include <QtCore/QObject>
#include <QtCore/QVector>

class QTimer;

namespace lk::ui {
class BusController;
}

/// `--sim-motion`: makes the drives of the built-in simulated bus move (speed steps every
/// two seconds) so that a demo or a documentation screenshot shows live plots. It sends only
/// on the simulator, through the normal bus path, and stops for good at the first
/// emergency stop.
class DemoMotion : public QObject {
    Q_OBJECT
public:
    explicit DemoMotion(lk::ui::BusController *controller, QObject *parent = nullptr);
    void start();

private:
    void step();

    lk::ui::BusController *m_controller;
    QTimer *m_timer;
    int m_phase = 0;
    bool m_stopped = false;
};
