#include "DemoMotion.h"

#include <main/BusController.h>
#include <main/StartupOptions.h>
#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>

#include <motor/SeriesLimits.h>
#include <protocol/Command.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QLoggingCategory>
#include <QtCore/QTimer>

Q_LOGGING_CATEGORY(lcDemo, "lk.studio.demo")

namespace {
constexpr double kShareOfMaxSpeed = 0.15; // gentle: a fraction of the series' top speed

/// A command the user sends when taking a drive over: anything that moves, switches or
/// stops a motor.
bool takesOver(lk::protocol::Command command)
{
    using lk::protocol::Command;
    return lk::protocol::CommandTable::info(command).movesMotor || command == Command::MotorOff ||
           command == Command::MotorStop || command == Command::MotorRun;
}
} // namespace

DemoMotion::DemoMotion(lk::ui::BusController *controller, int stepMs, QObject *parent)
    : QObject(parent), m_controller(controller), m_timer(new QTimer(this))
{
    m_timer->setInterval(stepMs);
    connect(m_timer, &QTimer::timeout, this, &DemoMotion::step);
    auto *session = m_controller->session();
    connect(session, &lk::bus::BusSession::emergencyStopFinished, this, [this] {
        m_tickets.clear();
        m_moved.clear(); // the stop turned them off
        stopForGood();
    });
    connect(session, &lk::bus::BusSession::requestCompleted, this, &DemoMotion::observe);
    connect(session, &lk::bus::BusSession::requestSubmitted, this,
            [this](quint64, const lk::protocol::Request &request, lk::bus::Priority priority) {
                if (!m_sending)
                    takeOver(request.id, request.command, priority);
            });
    // The first steps as soon as the drives are polled: a first run shows motion at once.
    connect(m_controller->model(), &lk::ui::BusModel::pollingChanged, this, [this] {
        if (m_running && m_moved.isEmpty() && canMove())
            step();
    });
}

bool DemoMotion::startsOnItsOwn(const lk::ui::StartupOptions &options,
                                const lk::ui::ConnectionChoice &choice)
{
    if (!choice.isSimulator())
        return false;
    return options.simMotion || (!options.sim && !options.port);
}

void DemoMotion::start()
{
    if (m_stopped || m_running)
        return;
    m_running = true;
    emit started();
    m_timer->start();
    qCInfo(lcDemo) << "demo motion on the simulated bus: the drives move until a command takes "
                      "over";
    if (canMove())
        step();
}

bool DemoMotion::canMove() const
{
    const auto *model = m_controller->model();
    return m_controller->simulator() && model->canSend() && model->isPolling() &&
           !model->ids().isEmpty();
}

void DemoMotion::step()
{
    if (!m_running)
        return;
    if (!m_controller->simulator()) {
        stopForGood(); // the user chose another bus: never move anything there
        return;
    }
    if (!canMove())
        return;
    ++m_phase;
    auto *model = m_controller->model();
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
        if (!built.ok())
            continue;
        m_sending = true;
        m_tickets.insert(m_controller->session()->send(*built.request));
        m_sending = false;
        m_moved.insert(ids[i]);
    }
}

void DemoMotion::observe(const lk::bus::RequestResult &result)
{
    // Commands from send() took over when they were submitted; this catches the rest (an
    // emergency lane's stop).
    if (!m_tickets.remove(result.ticket))
        takeOver(result.request.id, result.request.command, result.priority);
}

void DemoMotion::takeOver(int id, lk::protocol::Command command, lk::bus::Priority priority)
{
    if (!m_running || !takesOver(command))
        return;
    if (priority == lk::bus::Priority::Emergency) {
        // A stop from the emergency lane (leaving lkstudio, the speed watch): the others are
        // being stopped too; a speed 0 now would turn them on again behind their stop.
        qCInfo(lcDemo) << "demo motion ends: drive" << id << "was stopped";
        m_moved.clear();
        stopForGood();
        return;
    }
    qCInfo(lcDemo) << "demo motion ends: a command to drive" << id << "took over";
    standStill(id);
    stopForGood();
}

void DemoMotion::standStill(int except)
{
    if (!m_controller->simulator() || !m_controller->model()->canSend())
        return;
    for (int id : std::as_const(m_moved)) {
        if (id == except)
            continue;
        if (const auto built = lk::protocol::build::speed(id, 0); built.ok()) {
            m_sending = true;
            m_controller->session()->send(*built.request);
            m_sending = false;
        }
    }
    m_moved.clear();
}

void DemoMotion::stopForGood()
{
    m_timer->stop();
    m_stopped = true;
    if (!m_running)
        return;
    m_running = false;
    emit stopped();
}
