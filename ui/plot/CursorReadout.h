#pragma once

#include "PlotTrace.h"

#include <QtCore/QStringList>
#include <QtWidgets/QLabel>

#include <optional>

namespace lk::ui {

class TelemetryStore;

/// The line of text under the toolbar: every plotted value at the cursor time, or the
/// newest values while the mouse is off the charts. The step-test overlay words its hover
/// readout with the same pieces (line(), value()).
class CursorReadout : public QLabel {
    Q_OBJECT
public:
    explicit CursorReadout(QWidget *parent = nullptr);

    void showValues(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                    std::optional<double> cursorTime);
    /// Shows `text` (line()'s, or a hint) unless it is shown already.
    void showText(const QString &text);
    /// The text shown, grouped by drive: "t = 1.250 s   ID 1: iq 0.512 A, Speed 120.0 °/s".
    static QString format(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                          std::optional<double> cursorTime);
    /// "t = 1.250 s" (or "Latest" without a time) followed by each group's text.
    static QString line(std::optional<double> cursorTime, const QStringList &groups);
    /// One value: "iq 0.512 A"; "iq –" when there is none.
    static QString value(const QString &label, std::optional<double> v, int decimals,
                         const QString &unit);
};

} // namespace lk::ui
