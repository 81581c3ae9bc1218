#pragma once

#include <QtCore/QSortFilterProxyModel>

namespace lk::ui {

/// Shows the traffic rows of one ID and/or one command, or only faults and timeouts.
class TrafficFilter : public QSortFilterProxyModel {
    Q_OBJECT
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    void setIdFilter(int id);           ///< 0: every ID
    void setCommandFilter(int command); ///< wire code, -1: every command
    void setFaultsOnly(bool on);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    int m_id = 0;
    int m_command = -1;
    bool m_faultsOnly = false;
};

} // namespace lk::ui
