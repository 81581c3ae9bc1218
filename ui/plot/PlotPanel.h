#pragma once

#include "PlotTrace.h"
#include "TelemetryStore.h"
#include "TimeViewport.h"

#include <protocol/Series.h>
#include <record/TelemetryCsv.h>

#include <QtCore/QHash>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

#include <map>
#include <optional>

class QAction;
class QCheckBox;
class QComboBox;
class QMenu;
class QSplitter;
class QToolBar;
class QToolButton;

namespace lk::ui {

class CursorReadout;
class PollRateControl;
class StripChart;

/// Live plots of the selected drives: iq (power on MS), speed, encoder and multi-turn angle,
/// stacked (one chart per signal, shared time axis) or overlaid (one chart, one value axis per
/// unit); pause, time window, zoom/pan with "follow live", cursor readout, autoscale, poll
/// rate, CSV/PNG export. Redraws on a timer at most 25 Hz, only after a change, never while
/// hidden. The store is not owned and must outlive the panel.
class PlotPanel : public QWidget {
    Q_OBJECT
public:
    enum class Layout { Stacked, Overlaid };
    enum class ExportScope { VisibleRange, Everything };
    /// 25 Hz, PlotJuggler's rate: smooth to the eye. Each frame moves every time axis, and
    /// QtCharts rebuilds each line's path, hover outline and axis labels for it; drawing costs
    /// in proportion (60 Hz doubled the GUI's CPU time over 30 Hz for nothing the eye sees).
    static constexpr int kRedrawIntervalMs = 40;

    explicit PlotPanel(TelemetryStore *store, QWidget *parent = nullptr);
    ~PlotPanel() override;

    /// Drives to plot, in this order (duplicates dropped).
    void setDrives(const QVector<int> &ids);
    QVector<int> drives() const { return m_drives; }
    /// Labels the drive's torque trace as power (MS) or iq before its first sample says so;
    /// once samples arrive, what they carry wins.
    void setDriveSeries(int id, lk::protocol::Series series);

    /// The channels the signal picker offers, in display order: measuredChannels() as boxes,
    /// then commandedChannels() in the "Commanded" menu.
    static QVector<TelemetryChannel> pickableChannels();
    static QVector<TelemetryChannel> measuredChannels();
    static QVector<TelemetryChannel> commandedChannels();
    void setChannelVisible(TelemetryChannel channel, bool visible);
    bool isChannelVisible(TelemetryChannel channel) const;

    void setLayoutMode(Layout layout);
    Layout layoutMode() const { return m_layout; }
    /// While paused the charts hold still; the store keeps recording.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    /// Window length while following live (the combo offers 5 s .. 10 min).
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_viewport.window(); }
    void followLive();
    bool isFollowingLive() const { return m_viewport.isFollowing(); }
    void setAutoscale(bool on);
    bool autoscale() const { return m_autoscale; }

    /// Shows the poll rate in use (0 = max) without emitting pollRateRequested.
    void setPollRate(double hz);
    /// The bus limit for the current baud and motor count.
    void setBusLimit(double transactionsPerSecond, double cycleLimitHz);

    /// The time range on screen (or about to be, at the next redraw).
    TimeSpan visibleRange() const;
    /// Every plotted trace, by drive then channel (what the readout and CSV export use).
    QVector<PlotTrace> plottedTraces() const;
    /// Writes plotted traces to CSV in the layout chosen in the export menu (see
    /// PlotExporter::exportCsv). Error text, empty if ok.
    QString exportCsv(const QString &path, ExportScope scope) const;
    using CsvLayout = lk::record::CsvLayout;
    CsvLayout csvLayout() const { return m_csvLayout; }
    /// Writes the charts as PNG. Error text, empty if ok.
    QString exportPng(const QString &path);

    QList<StripChart *> charts() const { return m_charts; }
    /// Redraws done so far: lets tests and diagnostics see that the timer stays idle.
    quint64 redrawCount() const { return m_redraws; }

signals:
    /// The user asked for a poll rate; 0 = as fast as the bus allows.
    void pollRateRequested(double hz);

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QToolBar *buildToolbar();
    QWidget *buildSignalRow();
    QToolButton *buildCommandedButton(QWidget *parent);
    void updateCommandedButton();
    void markDirty();
    void onRedrawTimer();
    void redraw();
    void syncCharts();
    StripChart *addChart();
    void alignStackedCharts();
    void viewChanged();
    void setCursorTime(std::optional<double> time);
    QMenu *buildCsvMenu(QWidget *parent);
    void askExportCsv(ExportScope scope);
    void askExportPng();
    bool isPower(int id) const;
    QVector<PlotTrace> tracesFor(TelemetryChannel channel) const;
    double latestTime() const;

    TelemetryStore *m_store;
    QVector<int> m_drives;
    QHash<int, lk::protocol::Series> m_series;
    QVector<TelemetryChannel> m_channels;
    Layout m_layout = Layout::Stacked;
    bool m_paused = false;
    double m_pausedLatest = 0;
    std::optional<double> m_shownLatest; // newest time the last frame followed
    bool m_autoscale = true;
    CsvLayout m_csvLayout = CsvLayout::Wide;
    TimeViewport m_viewport;
    std::optional<double> m_cursor;
    QTimer m_redrawTimer;
    bool m_dirty = true;
    quint64 m_redraws = 0;

    QAction *m_pauseAction = nullptr;
    QAction *m_followAction = nullptr;
    QAction *m_overlayAction = nullptr;
    QAction *m_autoscaleAction = nullptr;
    QComboBox *m_windowCombo = nullptr;
    std::map<TelemetryChannel, QCheckBox *> m_channelBoxes;
    std::map<TelemetryChannel, QAction *> m_commandedActions;
    QToolButton *m_commandedButton = nullptr;
    PollRateControl *m_pollRate = nullptr;
    CursorReadout *m_readout = nullptr;
    QSplitter *m_chartArea = nullptr;
    QList<StripChart *> m_charts;
};

} // namespace lk::ui
