#pragma once

#include <QtCore/QAbstractTableModel>
#include <QtCore/QVector>

namespace lk::ui {

class BusModel;
struct DriveRecord;

/// One row per drive on the bus with its key values, flags and link figures (the overview
/// a field engineer reads at a glance). Reads BusModel; refresh() repaints the values.
class OverviewModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Id,
        Model,
        Series,
        Firmware,
        Link,
        Voltage,
        Temperature,
        Torque,
        Speed,
        Angle,
        Errors,
        Replies,
        Timeouts,
        ChecksumErrors,
        Latency,
        ColumnCount
    };

    explicit OverviewModel(BusModel *model, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    int idAt(int row) const { return row >= 0 && row < m_ids.size() ? m_ids[row] : 0; }
    int rowOf(int id) const { return m_ids.indexOf(id); }

public slots:
    void reload();  ///< the set of drives changed
    void refresh(); ///< values changed: repaint every cell

private:
    QVariant display(int id, int column) const;
    /// The cell shows a temperature or voltage outside its range (DriveHealth).
    static bool outOfRange(const DriveRecord &d, int column);
    bool isStale(int id, int column) const;

    BusModel *m_model;
    QVector<int> m_ids;
};

} // namespace lk::ui
