#include "TrafficFilter.h"

#include "TrafficModel.h"

#include <protocol/Command.h>

namespace lk::ui {

void TrafficFilter::setIdFilter(int id)
{
    m_id = id;
    invalidateFilter();
}

void TrafficFilter::setCommandFilter(int command)
{
    m_command = command;
    invalidateFilter();
}

void TrafficFilter::setFaultsOnly(bool on)
{
    m_faultsOnly = on;
    invalidateFilter();
}

void TrafficFilter::setHidePolling(bool on)
{
    m_hidePolling = on;
    invalidateFilter();
}

bool TrafficFilter::isPolling(int command)
{
    using protocol::Command;
    if (command < 0 || command > 0xFF)
        return false; // -1: a row without a command
    switch (Command(command)) {
    case Command::ReadEncoder:
    case Command::ReadMultiTurn:
    case Command::ReadSingleTurn:
    case Command::ReadState1:
    case Command::ReadState2:
    case Command::ReadState3:
        return true;
    default:
        return false;
    }
}

bool TrafficFilter::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (m_id == 0 && m_command < 0 && !m_faultsOnly && !m_hidePolling)
        return true;
    const QModelIndex i = sourceModel()->index(sourceRow, 0, sourceParent);
    if (m_id != 0 && i.data(TrafficModel::kIdRole).toInt() != m_id)
        return false;
    if (m_command >= 0 && i.data(TrafficModel::kCommandRole).toInt() != m_command)
        return false;
    const bool fault = i.data(TrafficModel::kIsFaultRole).toBool();
    if (m_faultsOnly && !fault)
        return false;
    if (m_hidePolling && !fault && isPolling(i.data(TrafficModel::kCommandRole).toInt()))
        return false;
    return true;
}

} // namespace lk::ui
