#include "DemoMotion.h"

#include <main/BusController.h>
#include <panels/BusModel.h>

#include <motor/SeriesLimits.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QTimer>

namespace {
constexpr int kStepMs = 2000;
constexpr double kShareOfMaxSpeed = 0.15; // gentle: a fraction of the series' top speed
} // namespace

DemoMotion::DemoMotion(lk::ui::BusController *controller, QObject *parent)
    : QObject(parent), m_controller(controller), m_timer(new QTimer(this))
{
    m_timer->setInterval(kStepMs);
    connect(m_timer, &QTimer::timeout, this, &DemoMotion::step);
    connect(m_controller->session(), &lk::bus::BusSession::emergencyStopFinished, this, [this] {
        m_stopped = true;
        m_timer->stop();
    });
}

void DemoMotion::start()
{
    if (!m_stopped)
        m_timer->start();
}

void DemoMotion::step()
{
    auto *model = m_controller->model();
    // Only ever on the built-in simulator, and only while it is up.
    if (!m_controller->simulator() || !model->canSend() || !model->isPolling())
        return;
    ++m_phase;
    const QVector<int> ids = model->ids();
    for (int i = 0; i < ids.size(); ++i) {
        const auto *d = model->drive(ids[i]);
        if (!d || !d->series)
            continue;
        const double top = lk::motor::seriesLimits(*d->series).maxSpeedDps() * kShareOfMaxSpeed;
        // Each drive its own pattern so that overlaid traces stay apart.
        const double sign = ((m_phase + i) % 3 == 0) ? -1.0 : 1.0;
        const double speed = sign * top * (0.4 + 0.2 * ((m_phase + i) % 4));
        const auto built = lk::protocol::build::speed(ids[i], speed);
        if (built.ok())
            m_controller->session()->send(*built.request);
    }
}
