#include "BusModel.h"

#include <text/VerdictText.h>

#include <array>
#include <vector>

namespace lk::ui {

namespace {

/// Which samples of `batch` the model must apply: what it shows of a drive is each field's
/// newest value, so a sample whose fields (and encoder reading) all come again later in the
/// batch for the same drive changes nothing that stays. A drive's last sample always applies
/// (its time and cycle). A replay's Load all hands on batches of thousands of samples a drive:
/// merging each of them was a tenth of the GUI thread's time.
std::vector<bool> samplesToApply(const bus::TelemetryBatch &batch)
{
    std::vector<bool> applies(size_t(batch.size()), true);
    std::array<bus::TelemetryFields, 256> later{};
    std::array<bool, 256> seen{};
    std::array<bool, 256> encoderLater{};
    for (qsizetype i = batch.size() - 1; i >= 0; --i) {
        const bus::TelemetrySample &s = batch.at(i);
        if (s.id < 0 || s.id >= int(later.size()))
            continue;
        const auto id = size_t(s.id);
        const bool newField = (s.fields & ~later[id]).toInt() != 0;
        const bool newEncoder = s.encoderReading && !encoderLater[id];
        applies[size_t(i)] = !seen[id] || newField || newEncoder;
        seen[id] = true;
        later[id] |= s.fields;
        encoderLater[id] = encoderLater[id] || s.encoderReading.has_value();
    }
    return applies;
}

} // namespace

BusModel::BusModel(QObject *parent) : QObject(parent)
{
    m_clock.start();
}

void BusModel::setConnection(const bus::ConnectionStatus &status, bool simulated)
{
    m_connection = status;
    m_simulated = simulated;
    if (!status.isOpen())
        setCanCondition(transport::CanBusCondition::Good); // the condition was the link's
    else if (status.link == protocol::Link::Can)
        // The engine reports each change of the CAN condition, its return to Good included
        // (error-passive ends only that way: no reply says so).
        setCanCondition(status.canCondition, status.conditionText);
    emit connectionChanged();
    // The figures belong to the link that was closed: the next one starts from nothing.
    if (status.state == transport::Transport::State::Closed && m_statistics.bus.requests > 0) {
        m_statistics = {};
        emit statisticsChanged();
    }
    if (status.state == transport::Transport::State::Closed && m_listenStatistics.bytes > 0) {
        m_listenStatistics = {};
        emit listenStatisticsChanged();
    }
}

void BusModel::setLinkGeneration(int id, protocol::Generation generation)
{
    auto it = m_drives.find(id);
    if (it == m_drives.end() || it->linkGeneration == generation)
        return;
    it->linkGeneration = generation;
    emit drivesChanged();
}

void BusModel::setChosenGearRatio(int id, double ratio)
{
    const auto it = m_drives.find(id);
    if (it == m_drives.end() || it->chosenGearRatio == ratio)
        return;
    it->chosenGearRatio = ratio;
    emit drivesChanged();
}

void BusModel::setLink(protocol::Link link, const QString &canInterface)
{
    // "tcp://127.0.0.1:35468/can0" (virtualcan) is channel can0 of its server.
    const QString name =
        link == protocol::Link::Can ? canInterface.section(QLatin1Char('/'), -1) : QString();
    if (m_link == link && m_canInterface == name)
        return;
    m_link = link;
    m_canInterface = name;
    emit connectionChanged();
}

void BusModel::setCanCondition(transport::CanBusCondition condition, const QString &message)
{
    const QString text = condition == transport::CanBusCondition::Good ? QString() : message;
    if (condition == m_canCondition && text == m_canMessage)
        return;
    m_canCondition = condition;
    m_canMessage = text;
    emit canConditionChanged();
}

QString BusModel::sendBlockedReason() const
{
    if (canSend())
        return {};
    if (isListening())
        return text::VerdictText::listenOnlyNoSend();
    return tr("Not connected: nothing can be sent.");
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

DriveRecord &BusModel::addObserved(int id)
{
    DriveRecord &d = m_drives[id];
    d.id = id;
    d.baud = m_connection.baud;
    return d;
}

void BusModel::addFound(const bus::FoundMotor &found)
{
    DriveRecord &d = m_drives[found.id];
    d.id = found.id;
    d.baud = found.baud;
    // On CAN nothing reads the model: an empty one would claim the V2.3 generation.
    if (found.link == protocol::Link::Can && !found.modelKnown)
        d.model.reset();
    else
        d.model = found.model;
    d.linkGeneration = found.generation;
    d.nameInfo = motor::ModelNameInfo::parse(found.model.motorName);
    d.series = found.series ? found.series : d.nameInfo.series;
    if (found.state1)
        d.apply(bus::TelemetrySample::fromState1(found.id, *found.state1, 0), nowMs());
    emit drivesChanged();
    selectArrived(found.id);
}

void BusModel::selectArrived(int id)
{
    if (id == m_wantedCurrent && (m_currentId == 0 || m_currentIsStandIn)) {
        setCurrent(id);
        if (!m_wantedSelection.isEmpty())
            setSelectedIds(m_wantedSelection); // those found so far; more come back below
    } else if (m_currentId == 0) {
        setCurrent(id);
        m_currentIsStandIn = m_wantedCurrent != 0; // until the wanted drive answers
    } else if (m_currentId == m_wantedCurrent && m_wantedSelection.contains(id) &&
               !m_selected.contains(id)) {
        setSelectedIds(m_selected + QVector<int>{id});
    }
}

void BusModel::applyKnownMotors(const bus::KnownMotors &motors)
{
    QVector<int> arrived;
    bool changed = false;
    for (const bus::KnownMotor &m : motors) {
        auto it = m_drives.find(m.id);
        if (it == m_drives.end()) {
            // A scan reports its drives itself (addFound); the bus's knowledge adds drives
            // only while listening, where no scan runs.
            if (!isListening())
                continue;
            addObserved(m.id);
            it = m_drives.find(m.id);
            arrived << m.id;
        }
        if (m.model && (!it->model || it->model->motorName != m.model->motorName ||
                        it->model->driverName != m.model->driverName)) {
            it->model = m.model;
            it->nameInfo = motor::ModelNameInfo::parse(m.model->motorName);
            changed = true;
        }
        // A series learnt (a 0x12 reply passed, or the user chose one) beats a name's guess.
        if (m.series && it->series != m.series) {
            it->series = m.series;
            changed = true;
        }
        // Without a model read: the generation a reply told or the user chose.
        if (!m.model && (m.identityChosen || m.generationSeen) &&
            it->linkGeneration != m.generation) {
            it->linkGeneration = m.generation;
            changed = true;
        }
    }
    if (!changed && arrived.isEmpty())
        return;
    emit drivesChanged();
    for (int id : arrived)
        selectArrived(id);
}

void BusModel::applyTelemetry(const bus::TelemetryBatch &batch)
{
    const qint64 now = nowMs();
    bool any = false;
    QVector<int> arrived;
    const std::vector<bool> applies = samplesToApply(batch);
    for (qsizetype i = 0; i < batch.size(); ++i) {
        const bus::TelemetrySample &s = batch.at(i);
        auto it = m_drives.find(s.id);
        if (it == m_drives.end()) {
            // Bus master: a reply from an ID the scan did not report is not shown until
            // scanned. Listening: no scan runs, and a drive that answers is on the bus.
            if (!isListening())
                continue;
            addObserved(s.id);
            it = m_drives.find(s.id);
            arrived << s.id;
        }
        if (applies[size_t(i)])
            it->apply(s, now);
        any = true;
    }
    if (!arrived.isEmpty())
        emit drivesChanged();
    for (int id : arrived)
        selectArrived(id);
    // A drive's reply crossed the bus: it is not bus-off, and a frame was acknowledged.
    if (!batch.isEmpty() && (m_canCondition == transport::CanBusCondition::BusOff ||
                             m_canCondition == transport::CanBusCondition::NoAcknowledge))
        setCanCondition(transport::CanBusCondition::Good);
    if (any)
        emit telemetryChanged();
}

void BusModel::setStatistics(const bus::BusStatistics &statistics)
{
    m_statistics = statistics;
    emit statisticsChanged();
}

void BusModel::setListenStatistics(const bus::ListenStatistics &statistics)
{
    m_listenStatistics = statistics;
    emit listenStatisticsChanged();
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
