#pragma once

#include "PlotTrace.h"
#include "TelemetryStore.h"

#include <record/TelemetryCsv.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QDateTime>
#include <QtCore/QString>

#include <optional>

class QWidget;

namespace lk::ui {

/// Writes what the plot shows to files, without dialogs (the panel's buttons add those).
class PlotExporter {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::PlotExporter)
public:
    /// CSV of `traces` between `span.begin` and `span.end` (inclusive), every recorded point
    /// (not the decimated ones), in the schema of docs/CSV.md shared with `lkctl monitor`:
    /// wide (time_s, then "id<drive>_<column>" per trace, e.g. id3_iq_a) or long (time_s, id,
    /// then the traces' columns). One row per poll round (per drive and round in the long
    /// layout) stamped with the round's time; a point that answered no poll (an operator's
    /// read, a command's reply) gets a row of its own at its own time. Returns an error text,
    /// empty on success.
    static QString exportCsv(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                             TimeSpan span, const QString &path, lk::record::CsvLayout layout);
    /// The widget as it looks now, as PNG, under a title line (what, which drives, when): the
    /// title of the PlotPanel the widget is in (pngTitle() of its plotted traces, now), or
    /// none outside a plot panel. The title is also the PNG's "Title" text. Returns an error
    /// text, empty on success.
    static QString exportPng(QWidget *widget, const QString &path);
    /// The same with `title` given (empty: no title line).
    static QString exportPng(QWidget *widget, const QString &path, const QString &title);
    /// "Speed, iq — drives 1, 3 — 2026-11-27 14:05:09": the plotted signals in plot order,
    /// the drives ascending, and `when` (local time).
    static QString pngTitle(const QVector<PlotTrace> &traces, const QDateTime &when);
    /// The TelemetryColumns index a trace is written as.
    static int columnOf(const PlotTrace &trace);
};

} // namespace lk::ui
