#include "EmergencyStopControl.h"

#include "BusController.h"
#include "CommandedMotion.h"
#include "EmergencyKeyFilter.h"
#include "EmergencyStopReport.h"

#include <panels/BusModel.h>
#include <panels/MessageBanner.h>

#include <bus/BusSession.h>

#include <QtWidgets/QApplication>

#include <algorithm>

namespace lk::ui {

EmergencyStopControl::EmergencyStopControl(BusController *controller, CommandedMotion *motion,
                                           MessageBanner *banner, QObject *parent)
    : QObject(parent), m_controller(controller), m_motion(motion), m_banner(banner),
      m_keys(new EmergencyKeyFilter(this))
{
    qApp->installEventFilter(m_keys);
    connect(m_keys, &EmergencyKeyFilter::escapePressed, this, &EmergencyStopControl::stop);
    bus::BusSession *session = m_controller->session();
    connect(session, &bus::BusSession::emergencyStopFinished, this,
            &EmergencyStopControl::onFinished);
}

EmergencyStopControl::~EmergencyStopControl()
{
    qApp->removeEventFilter(m_keys);
}

void EmergencyStopControl::stop()
{
    emit halting(tr("Emergency stop."));
    Pending p;
    // Whom to reach first: the drives on screen, those the bus knows, and those lkstudio told
    // to move (a scan may have just emptied the first two). The bus adds every other ID.
    p.watched = m_controller->model()->ids() + m_motion->movingIds();
    for (int id : m_controller->session()->knownMotors().keys())
        p.watched.append(id);
    std::sort(p.watched.begin(), p.watched.end());
    p.watched.erase(std::unique(p.watched.begin(), p.watched.end()), p.watched.end());
    for (int id : m_motion->movingIds())
        p.commanded << m_motion->driveText(id);
    m_pending.insert(m_controller->emergencyStop(p.watched), p);
}

void EmergencyStopControl::onFinished(quint64 ticket, const QVector<int> &acknowledged,
                                      const QVector<int> &silent, const QVector<int> &unsent)
{
    const auto it = m_pending.find(ticket);
    if (it == m_pending.end())
        return;
    const Pending p = *it;
    m_pending.erase(it);
    report(p, {acknowledged, silent, unsent});
    emit reported();
}

void EmergencyStopControl::report(const Pending &p, const Outcome &outcome)
{
    const EmergencyStopReport::Text text = EmergencyStopReport::compose(p, outcome);
    m_banner->setEntry(entryKey(), text.level, text.html);
}

} // namespace lk::ui
