#pragma once

#include <QtWidgets/QWidget>

namespace lk::ui {

class BusModel;
class DriveTree;
class ScanControls;

/// The left dock: scan controls above the tree of drives found on the bus.
class BusPanel : public QWidget {
    Q_OBJECT
public:
    explicit BusPanel(BusModel *model, QWidget *parent = nullptr);
    ScanControls *scanControls() const { return m_scan; }
    DriveTree *tree() const { return m_tree; }
    /// Wide enough for the drive list's columns without scrolling.
    QSize sizeHint() const override;

private:
    ScanControls *m_scan;
    DriveTree *m_tree;
};

} // namespace lk::ui
