#pragma once

#include <QtWidgets/QTreeWidget>

class QTimer;

namespace lk::ui {

class BusModel;

/// The bus and the drives found on it: ID, model, series, versions, voltage, temperature and
/// error flags (low voltage / over temperature in red with an icon). Selecting a row selects
/// the drive in every view.
class DriveTree : public QTreeWidget {
    Q_OBJECT
public:
    enum Column {
        IdCol,
        ModelCol,
        SeriesCol,
        FirmwareCol,
        HardwareCol,
        VoltageCol,
        TempCol,
        ErrorsCol,
        ColumnCount
    };

    explicit DriveTree(BusModel *model, QWidget *parent = nullptr);

    QTreeWidgetItem *itemForId(int id) const;

private:
    void rebuild();
    void refreshValues();
    void updateBusItem();
    void updateItem(QTreeWidgetItem *item, int id);
    void selectCurrent();

    BusModel *m_model;
    QTreeWidgetItem *m_bus = nullptr;
    QTimer *m_refresh = nullptr;
    bool m_dirty = false;
    bool m_choosing = false; ///< a click here is being handed to the model
};

} // namespace lk::ui
