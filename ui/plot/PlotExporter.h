#pragma once

#include "PlotTrace.h"
#include "TelemetryStore.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

class QWidget;

namespace lk::ui {

/// Writes what the plot shows to files, without dialogs (the panel's buttons add those).
class PlotExporter {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::PlotExporter)
public:
    /// CSV of `traces` between `span.begin` and `span.end` (inclusive), every recorded
    /// point (not the decimated ones): `time_s` then one column per trace named
    /// "id<drive>_<key>" (e.g. id3_iq_a), one row per distinct timestamp (see
    /// lk::record::CsvWriter::writeAligned). Returns an error text, empty on success.
    static QString exportCsv(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                             TimeSpan span, const QString &path);
    /// The widget as it looks now, as PNG. Returns an error text, empty on success.
    static QString exportPng(QWidget *widget, const QString &path);
    /// Header name of a trace's column.
    static QString columnName(const PlotTrace &trace);
};

} // namespace lk::ui
