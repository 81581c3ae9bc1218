#pragma once

#include <QtWidgets/QWidget>

namespace lk::ui {

class BusModel;
class DriveTree;
class ScanControls;
class SeriesChooser;

/// The left dock: scan controls above the tree of drives found on the bus (or seen while
/// listening), and the series chooser for a drive whose series is unknown.
class BusPanel : public QWidget {
    Q_OBJECT
public:
    explicit BusPanel(BusModel *model, QWidget *parent = nullptr);
    ScanControls *scanControls() const { return m_scan; }
    DriveTree *tree() const { return m_tree; }
    SeriesChooser *seriesChooser() const { return m_series; }
    /// Wide enough for the drive list's columns without scrolling.
    QSize sizeHint() const override;

private:
    ScanControls *m_scan;
    DriveTree *m_tree;
    SeriesChooser *m_series;
};

} // namespace lk::ui
