#pragma once

#include <QtCore/QSortFilterProxyModel>

namespace lk::ui {

/// Shows the traffic rows of one ID and/or one command, or only faults and timeouts, or
/// everything but the polling (so that the commands among the polls stand out).
class TrafficFilter : public QSortFilterProxyModel {
    Q_OBJECT
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    void setIdFilter(int id);           ///< 0: every ID
    void setCommandFilter(int command); ///< wire code, -1: every command
    void setFaultsOnly(bool on);
    /// Hide the requests and replies of the state reads a poll round is made of (isPolling);
    /// faults, timeouts and notes stay.
    void setHidePolling(bool on);
    bool hidesPolling() const { return m_hidePolling; }
    /// The reads a master polls the drives with: encoder, angles and the three states.
    static bool isPolling(int command);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    int m_id = 0;
    int m_command = -1;
    bool m_faultsOnly = false;
    bool m_hidePolling = false;
};

} // namespace lk::ui
