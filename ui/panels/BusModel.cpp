#include "BusModel.h"

namespace lk::ui {

BusModel::BusModel(QObject *parent) : QObject(parent)
{
    m_clock.start();
}

void BusModel::setConnection(const bus::ConnectionStatus &status, bool simulated)
{
    m_connection = status;
    m_simulated = simulated;
    emit connectionChanged();
    // The figures belong to the link that was closed: the next one starts from nothing.
    if (status.state == transport::Transport::State::Closed && m_statistics.bus.requests > 0) {
        m_statistics = {};
        emit statisticsChanged();
    }
}

const DriveRecord *BusModel::drive(int id) const
{
    const auto it = m_drives.constFind(id);
    return it == m_drives.constEnd() ? nullptr : &it.value();
}

void BusModel::clearDrives()
{
    // A rescan or a reconnect finds the same drives again: the user's choice comes back with
    // them (addFound) instead of falling to the first drive found.
    if (m_currentId != 0 && !m_currentIsStandIn) {
        m_wantedCurrent = m_currentId;
        m_wantedSelection = m_selected;
    }
    m_drives.clear();
    emit drivesChanged();
    setCurrent(0);
    setSelectedIds({});
}

void BusModel::addFound(const bus::FoundMotor &found)
{
    DriveRecord &d = m_drives[found.id];
    d.id = found.id;
    d.baud = found.baud;
    d.model = found.model;
    d.nameInfo = motor::ModelNameInfo::parse(found.model.motorName);
    d.series = found.series ? found.series : d.nameInfo.series;
    if (found.state1)
        d.apply(bus::TelemetrySample::fromState1(found.id, *found.state1, 0), nowMs());
    emit drivesChanged();
    if (found.id == m_wantedCurrent && (m_currentId == 0 || m_currentIsStandIn)) {
        setCurrent(found.id);
        if (!m_wantedSelection.isEmpty())
            setSelectedIds(m_wantedSelection); // those found so far; more come back below
    } else if (m_currentId == 0) {
        setCurrent(found.id);
        m_currentIsStandIn = m_wantedCurrent != 0; // until the wanted drive answers
    } else if (m_currentId == m_wantedCurrent && m_wantedSelection.contains(found.id) &&
               !m_selected.contains(found.id)) {
        setSelectedIds(m_selected + QVector<int>{found.id});
    }
}

void BusModel::applyTelemetry(const bus::TelemetryBatch &batch)
{
    const qint64 now = nowMs();
    bool any = false;
    for (const auto &s : batch) {
        auto it = m_drives.find(s.id);
        if (it == m_drives.end())
            continue; // a reply from an ID the scan did not report: not shown until scanned
        it->apply(s, now);
        any = true;
    }
    if (any)
        emit telemetryChanged();
}

void BusModel::setStatistics(const bus::BusStatistics &statistics)
{
    m_statistics = statistics;
    emit statisticsChanged();
}

void BusModel::setPolling(const bus::PollPlan &plan, bool active)
{
    m_pollPlan = plan;
    m_polling = active;
    emit pollingChanged();
}

double BusModel::requestedTransactionsPerSecond() const
{
    if (!m_polling || m_pollPlan.rateHz <= 0)
        return 0;
    int perCycle = 0;
    for (int id : m_pollPlan.ids) {
        const DriveRecord *d = drive(id);
        for (auto c : m_pollPlan.commands) {
            if (c == protocol::Command::ReadState3 && d && !d->hasPhaseCurrents())
                continue;
            ++perCycle;
        }
    }
    return perCycle * m_pollPlan.rateHz;
}

void BusModel::setCurrentId(int id)
{
    if (id != 0 && !m_drives.contains(id))
        return;
    // The user's own choice: it is what comes back after the next reconnect.
    m_wantedCurrent = id;
    m_wantedSelection.clear();
    setCurrent(id);
}

void BusModel::setCurrent(int id)
{
    m_currentIsStandIn = false;
    if (id == m_currentId)
        return;
    m_currentId = id;
    emit currentDriveChanged(id);
    if (!m_selected.contains(id))
        setSelectedIds(id ? QVector<int>{id} : QVector<int>{});
    else
        emit selectionChanged(); // the fallback of selectedIds() may have changed
}

QVector<int> BusModel::selectedIds() const
{
    if (!m_selected.isEmpty())
        return m_selected;
    return m_currentId ? QVector<int>{m_currentId} : QVector<int>{};
}

void BusModel::setSelectedIds(const QVector<int> &ids)
{
    QVector<int> known;
    for (int id : ids) {
        if (m_drives.contains(id) && !known.contains(id))
            known << id;
    }
    if (known == m_selected)
        return;
    m_selected = known;
    emit selectionChanged();
}

} // namespace lk::ui
