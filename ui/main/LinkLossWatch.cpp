#include "LinkLossWatch.h"

#include "CommandedMotion.h"

#include <panels/BusModel.h>
#include <panels/MessageBanner.h>

#include <algorithm>

namespace lk::ui {

LinkLossWatch::LinkLossWatch(BusModel *model, CommandedMotion *motion, MessageBanner *banner,
                             QObject *parent)
    : QObject(parent), m_model(model), m_motion(motion), m_banner(banner),
      m_wasOpen(model->connection().isOpen())
{
    connect(m_model, &BusModel::connectionChanged, this, &LinkLossWatch::onConnectionChanged);
    connect(m_banner, &MessageBanner::entryDismissed, this, [this](const QString &key) {
        for (int id : warnedIds()) {
            if (key == entryKey(id))
                m_warned.remove(id); // the user acknowledged it
        }
    });
}

QVector<int> LinkLossWatch::warnedIds() const
{
    QVector<int> ids(m_warned.cbegin(), m_warned.cend());
    std::sort(ids.begin(), ids.end());
    return ids;
}

void LinkLossWatch::onConnectionChanged()
{
    const bool open = m_model->connection().isOpen();
    if (m_wasOpen && !open) {
        for (int id : m_motion->movingIds())
            warn(id);
    }
    m_wasOpen = open;
}

void LinkLossWatch::warn(int id)
{
    const std::optional<CommandedMotion::Entry> last = m_motion->last(id);
    if (!last)
        return;
    m_warned.insert(id);
    m_banner->setEntry(
        entryKey(id), MessageBanner::Level::Warning,
        tr("<b>Drive %1 may still be moving</b>: last command %2 at %3; it stops by itself only "
           "if its input-timeout protection is set.")
            .arg(id)
            .arg(CommandedMotion::describe(last->request).toHtmlEscaped(),
                 last->sentAt.time().toString(QStringLiteral("HH:mm:ss"))));
}

void LinkLossWatch::clear(int id)
{
    m_warned.remove(id);
    m_banner->clearEntry(entryKey(id));
}

void LinkLossWatch::onTelemetry(const bus::TelemetryBatch &batch)
{
    // Samples arrive only while the link is open, after the status that said so: a sample
    // seen now was read after the reconnect.
    if (m_warned.isEmpty() || !m_model->connection().isOpen())
        return;
    for (const bus::TelemetrySample &s : batch) {
        if (m_warned.contains(s.id) && s.has(bus::TelemetryField::Speed) && s.speedDps == 0)
            clear(s.id);
    }
}

} // namespace lk::ui
