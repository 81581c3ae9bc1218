#include "EmergencyStopControl.h"

#include "BusController.h"
#include "CommandedMotion.h"
#include "EmergencyKeyFilter.h"

#include <panels/BusModel.h>
#include <panels/MessageBanner.h>
#include <panels/StatusColors.h>

#include <bus/BusSession.h>

#include <QtWidgets/QApplication>

#include <algorithm>

namespace lk::ui {

namespace {
QString idList(const QVector<int> &ids)
{
    QStringList parts;
    for (int id : ids)
        parts << QString::number(id);
    return parts.join(QStringLiteral(", "));
}

QString redBold(const QString &html)
{
    return QStringLiteral("<b><span style=\"color:%1\">%2</span></b>")
        .arg(StatusColors::text(StatusColors::Role::Error).name(), html);
}
} // namespace

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
    using Level = MessageBanner::Level;
    const QVector<int> &acknowledged = outcome.acknowledged;
    const int total = int(acknowledged.size() + outcome.silent.size());
    const int sent = total - int(outcome.unsent.size());
    if (sent == 0) {
        const QString what =
            p.commanded.isEmpty()
                ? tr("Emergency stop: NOTHING could be sent, the bus is not connected. lkstudio "
                     "has not commanded any drive to move.")
                : tr("Emergency stop: NOTHING could be sent, the bus is not connected. Last "
                     "commanded to move: %1. They may still be moving: cut their power if "
                     "needed.")
                      .arg(p.commanded.join(QStringLiteral("; ")).toHtmlEscaped());
        m_banner->setEntry(entryKey(), Level::Error, redBold(what));
        return;
    }
    QVector<int> missing;
    for (int id : outcome.silent) {
        if (p.watched.contains(id))
            missing.append(id);
    }
    QString text =
        acknowledged.isEmpty()
            ? tr("Emergency stop: Motor Off sent to %n ID(s); no drive answered.", nullptr, sent)
            : tr("Emergency stop: Motor Off sent to %n ID(s); acknowledged by "
                 "drive(s) %1.",
                 nullptr, sent)
                  .arg(idList(acknowledged));
    if (sent < total)
        text += QLatin1Char(' ') +
                tr("%1 of %2 could not be sent: the link dropped.").arg(total - sent).arg(total);
    text = text.toHtmlEscaped();
    if (!missing.isEmpty())
        text += QLatin1Char(' ') +
                redBold(tr("NO answer from drive(s) %1: check them and cut their power if needed.")
                            .arg(idList(missing)));
    const Level level = !missing.isEmpty() || sent < total ? Level::Error
                        : acknowledged.isEmpty()           ? Level::Warning
                                                           : Level::Info;
    m_banner->setEntry(entryKey(), level, text);
}

} // namespace lk::ui
