#include "TrafficFilter.h"

#include "TrafficModel.h"

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

bool TrafficFilter::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (m_id == 0 && m_command < 0 && !m_faultsOnly)
        return true;
    const QModelIndex i = sourceModel()->index(sourceRow, 0, sourceParent);
    if (m_id != 0 && i.data(TrafficModel::kIdRole).toInt() != m_id)
        return false;
    if (m_command >= 0 && i.data(TrafficModel::kCommandRole).toInt() != m_command)
        return false;
    if (m_faultsOnly && !i.data(TrafficModel::kIsFaultRole).toBool())
        return false;
    return true;
}

} // namespace lk::ui
