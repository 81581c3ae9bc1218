#pragma once

#include "PlotTrace.h"

#include <QtWidgets/QLabel>

#include <optional>

namespace lk::ui {

class TelemetryStore;

/// The line of text under the toolbar: every plotted value at the cursor time, or the
/// newest values while the mouse is off the charts.
class CursorReadout : public QLabel {
    Q_OBJECT
public:
    explicit CursorReadout(QWidget *parent = nullptr);

    void showValues(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                    std::optional<double> cursorTime);
    /// The text shown, grouped by drive: "t = 1.250 s   ID 1: iq 0.512 A, Speed 120.0 °/s".
    static QString format(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                          std::optional<double> cursorTime);
};

} // namespace lk::ui
