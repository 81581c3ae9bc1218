#include "PlotPanel.h"

#include "CursorReadout.h"
#include "PlotExporter.h"
#include "PollRateControl.h"
#include "StripChart.h"

#include <panels/FileDialogs.h>

#include <QtCore/QDateTime>
#include <QtCore/QEvent>
#include <QtCore/QSignalBlocker>
#include <QtGui/QActionGroup>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

#include <limits>

namespace lk::ui {

namespace {

constexpr int kMinimizedRetryMs = 250; // minimized windows are checked rarely, not drawn
constexpr int kMinChartHeight = 170;   // below it axis labels and titles turn into "..."

struct WindowPreset {
    double seconds;
    const char *label;
};
const WindowPreset kWindowPresets[] = {
    {5, QT_TRANSLATE_NOOP("lk::ui::PlotPanel", "5 s")},
    {10, QT_TRANSLATE_NOOP("lk::ui::PlotPanel", "10 s")},
    {30, QT_TRANSLATE_NOOP("lk::ui::PlotPanel", "30 s")},
    {60, QT_TRANSLATE_NOOP("lk::ui::PlotPanel", "1 min")},
    {300, QT_TRANSLATE_NOOP("lk::ui::PlotPanel", "5 min")},
    {600, QT_TRANSLATE_NOOP("lk::ui::PlotPanel", "10 min")},
};

} // namespace

PlotPanel::PlotPanel(TelemetryStore *store, QWidget *parent)
    : QWidget(parent), m_store(store), m_channels{TelemetryChannel::Torque, TelemetryChannel::Speed,
                                                  TelemetryChannel::Encoder}
{
    Q_ASSERT(store);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(buildToolbar());
    layout->addWidget(buildSignalRow());
    m_readout = new CursorReadout(this);
    layout->addWidget(m_readout);
    m_chartArea = new QSplitter(Qt::Vertical, this);
    m_chartArea->setChildrenCollapsible(false);
    layout->addWidget(m_chartArea, 1);

    m_redrawTimer.setSingleShot(true);
    m_redrawTimer.setInterval(kRedrawIntervalMs);
    connect(&m_redrawTimer, &QTimer::timeout, this, &PlotPanel::onRedrawTimer);
    connect(m_store, &TelemetryStore::dataAppended, this, [this] {
        if (!m_paused) {
            markDirty();
        }
    });
    connect(m_store, &TelemetryStore::cleared, this, &PlotPanel::markDirty);
    syncCharts();
}

PlotPanel::~PlotPanel() = default;

QToolBar *PlotPanel::buildToolbar()
{
    auto *bar = new QToolBar(this);
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_pauseAction = bar->addAction(tr("Pause"));
    m_pauseAction->setCheckable(true);
    m_pauseAction->setToolTip(tr("Freeze the plots; recording goes on"));
    connect(m_pauseAction, &QAction::toggled, this, &PlotPanel::setPaused);
    m_followAction = bar->addAction(tr("Follow live"));
    m_followAction->setToolTip(tr("Return to the newest data after zooming or panning"));
    m_followAction->setEnabled(false);
    connect(m_followAction, &QAction::triggered, this, &PlotPanel::followLive);

    bar->addWidget(new QLabel(tr("Window:"), bar));
    m_windowCombo = new QComboBox(bar);
    for (const WindowPreset &preset : kWindowPresets) {
        m_windowCombo->addItem(tr(preset.label), preset.seconds);
    }
    m_windowCombo->setCurrentIndex(m_windowCombo->findData(m_viewport.window()));
    connect(m_windowCombo, &QComboBox::currentIndexChanged, this,
            [this](int index) { setWindowSeconds(m_windowCombo->itemData(index).toDouble()); });
    bar->addWidget(m_windowCombo);

    m_overlayAction = bar->addAction(tr("Overlay"));
    m_overlayAction->setCheckable(true);
    m_overlayAction->setToolTip(tr("One chart with a value axis per unit instead of stacked "
                                   "charts"));
    connect(m_overlayAction, &QAction::toggled, this,
            [this](bool on) { setLayoutMode(on ? Layout::Overlaid : Layout::Stacked); });
    m_autoscaleAction = bar->addAction(tr("Autoscale"));
    m_autoscaleAction->setCheckable(true);
    m_autoscaleAction->setChecked(true);
    m_autoscaleAction->setToolTip(tr("Fit the value axes to the data (Ctrl+wheel scales them "
                                     "by hand)"));
    connect(m_autoscaleAction, &QAction::toggled, this, &PlotPanel::setAutoscale);
    bar->addSeparator();

    auto *csvButton = new QToolButton(bar);
    csvButton->setText(tr("Export CSV"));
    csvButton->setMenu(buildCsvMenu(bar));
    csvButton->setPopupMode(QToolButton::InstantPopup);
    bar->addWidget(csvButton);
    connect(bar->addAction(tr("Export PNG…")), &QAction::triggered, this, &PlotPanel::askExportPng);
    return bar;
}

QWidget *PlotPanel::buildSignalRow()
{
    auto *row = new QWidget(this);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(4, 0, 4, 0);
    layout->addWidget(new QLabel(tr("Signals:"), row));
    // What the drive reports as two rows of three boxes; what a master commanded (six more
    // signals, read on a listen-only link) behind one menu button: with every signal as a box
    // the row would pass a 1366-pixel screen.
    auto *boxes = new QGridLayout;
    boxes->setVerticalSpacing(0);
    const QVector<TelemetryChannel> measured = measuredChannels();
    for (int i = 0; i < measured.size(); ++i) {
        const TelemetryChannel channel = measured.at(i);
        auto *box = new QCheckBox(channelPickerLabel(channel), row);
        box->setChecked(m_channels.contains(channel));
        connect(box, &QCheckBox::toggled, this,
                [this, channel](bool on) { setChannelVisible(channel, on); });
        m_channelBoxes[channel] = box;
        boxes->addWidget(box, i / 3, i % 3);
    }
    layout->addLayout(boxes);
    layout->addWidget(buildCommandedButton(row));
    layout->addStretch(1);
    m_pollRate = new PollRateControl(row);
    connect(m_pollRate, &PollRateControl::pollRateRequested, this, &PlotPanel::pollRateRequested);
    layout->addWidget(m_pollRate);
    return row;
}

QToolButton *PlotPanel::buildCommandedButton(QWidget *parent)
{
    m_commandedButton = new QToolButton(parent);
    m_commandedButton->setObjectName(QStringLiteral("commandedSignals"));
    m_commandedButton->setPopupMode(QToolButton::InstantPopup);
    m_commandedButton->setToolTip(tr("What a master commanded, beside what the drive replied "
                                     "(the other master's commands on a listen-only link)"));
    auto *menu = new QMenu(m_commandedButton);
    for (const TelemetryChannel channel : commandedChannels()) {
        QAction *action = menu->addAction(channelPickerLabel(channel));
        action->setCheckable(true);
        action->setChecked(m_channels.contains(channel));
        connect(action, &QAction::toggled, this,
                [this, channel](bool on) { setChannelVisible(channel, on); });
        m_commandedActions[channel] = action;
    }
    m_commandedButton->setMenu(menu);
    updateCommandedButton();
    return m_commandedButton;
}

void PlotPanel::updateCommandedButton()
{
    int shown = 0;
    for (const TelemetryChannel channel : commandedChannels())
        shown += m_channels.contains(channel) ? 1 : 0;
    m_commandedButton->setText(shown == 0 ? tr("Commanded") : tr("Commanded (%1)").arg(shown));
}

QVector<TelemetryChannel> PlotPanel::measuredChannels()
{
    return {TelemetryChannel::Torque,    TelemetryChannel::Speed,       TelemetryChannel::Encoder,
            TelemetryChannel::MultiTurn, TelemetryChannel::Temperature, TelemetryChannel::Voltage};
}

QVector<TelemetryChannel> PlotPanel::commandedChannels()
{
    return {TelemetryChannel::CommandedTorque,    TelemetryChannel::CommandedSpeed,
            TelemetryChannel::CommandedAngle,     TelemetryChannel::CommandedSingleTurn,
            TelemetryChannel::CommandedIncrement, TelemetryChannel::CommandedMaxSpeed};
}

QVector<TelemetryChannel> PlotPanel::pickableChannels()
{
    return measuredChannels() + commandedChannels();
}

void PlotPanel::setDrives(const QVector<int> &ids)
{
    QVector<int> unique;
    for (int id : ids) {
        if (!unique.contains(id)) {
            unique.append(id);
        }
    }
    if (unique != m_drives) {
        m_drives = unique;
        syncCharts(); // the structure now, the data at the next tick
        markDirty();
    }
}

void PlotPanel::setDriveSeries(int id, lk::protocol::Series series)
{
    m_series.insert(id, series);
    syncCharts();
    markDirty();
}

void PlotPanel::setChannelVisible(TelemetryChannel channel, bool visible)
{
    const QVector<TelemetryChannel> order = pickableChannels();
    if (!order.contains(channel) || visible == m_channels.contains(channel)) {
        return;
    }
    QVector<TelemetryChannel> next;
    for (TelemetryChannel c : order) {
        if (c == channel ? visible : m_channels.contains(c)) {
            next.append(c);
        }
    }
    m_channels = next;
    if (const auto box = m_channelBoxes.find(channel); box != m_channelBoxes.end()) {
        const QSignalBlocker block(box->second);
        box->second->setChecked(visible);
    } else if (QAction *action = m_commandedActions.at(channel)) {
        const QSignalBlocker block(action);
        action->setChecked(visible);
        updateCommandedButton();
    }
    syncCharts();
    markDirty();
}

bool PlotPanel::isChannelVisible(TelemetryChannel channel) const
{
    return m_channels.contains(channel);
}

void PlotPanel::setLayoutMode(Layout layout)
{
    if (layout == m_layout) {
        return;
    }
    m_layout = layout;
    const QSignalBlocker block(m_overlayAction);
    m_overlayAction->setChecked(layout == Layout::Overlaid);
    syncCharts();
    markDirty();
}

void PlotPanel::setPaused(bool paused)
{
    if (paused == m_paused) {
        return;
    }
    // Freeze exactly what is on screen; data that came after the last frame stays unseen.
    m_pausedLatest = m_shownLatest.value_or(latestTime());
    m_paused = paused;
    const QSignalBlocker block(m_pauseAction);
    m_pauseAction->setChecked(paused);
    if (!paused) {
        markDirty();
    }
}

void PlotPanel::setWindowSeconds(double seconds)
{
    m_viewport.setWindow(seconds);
    const QSignalBlocker block(m_windowCombo);
    m_windowCombo->setCurrentIndex(m_windowCombo->findData(m_viewport.window()));
    viewChanged();
}

void PlotPanel::followLive()
{
    m_viewport.follow();
    viewChanged();
}

void PlotPanel::setAutoscale(bool on)
{
    m_autoscale = on;
    const QSignalBlocker block(m_autoscaleAction);
    m_autoscaleAction->setChecked(on);
    markDirty();
}

void PlotPanel::setPollRate(double hz)
{
    m_pollRate->setPollRate(hz);
}

void PlotPanel::setBusLimit(double transactionsPerSecond, double cycleLimitHz)
{
    m_pollRate->setBusLimit(transactionsPerSecond, cycleLimitHz);
}

double PlotPanel::latestTime() const
{
    if (m_paused) {
        return m_pausedLatest;
    }
    const std::optional<TimeSpan> span = m_store->timeSpan();
    return span ? span->end : 0.0;
}

TimeSpan PlotPanel::visibleRange() const
{
    return m_viewport.range(latestTime());
}

bool PlotPanel::isPower(int id) const
{
    if (const std::optional<bool> power = m_store->torqueIsPower(id)) {
        return *power;
    }
    return m_series.value(id, lk::protocol::Series::MF) == lk::protocol::Series::MS;
}

QVector<PlotTrace> PlotPanel::tracesFor(TelemetryChannel channel) const
{
    QVector<PlotTrace> traces;
    for (int id : m_drives) {
        traces.append({id, channel, hasPowerColumn(channel) && isPower(id)});
    }
    return traces;
}

QVector<PlotTrace> PlotPanel::plottedTraces() const
{
    QVector<PlotTrace> traces;
    for (int id : m_drives) {
        for (TelemetryChannel channel : m_channels) {
            traces.append({id, channel, hasPowerColumn(channel) && isPower(id)});
        }
    }
    return traces;
}

void PlotPanel::markDirty()
{
    m_dirty = true;
    if (isVisible() && !m_redrawTimer.isActive()) {
        m_redrawTimer.start(kRedrawIntervalMs);
    }
}

void PlotPanel::viewChanged()
{
    m_followAction->setEnabled(!m_viewport.isFollowing());
    markDirty();
}

void PlotPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty) {
        markDirty();
    }
}

void PlotPanel::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_redrawTimer.stop(); // hidden panels cost nothing; showEvent resumes
}

bool PlotPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Resize) {
        markDirty(); // a new width means new pixel columns
    }
    return QWidget::eventFilter(watched, event);
}

void PlotPanel::onRedrawTimer()
{
    if (!m_dirty || !isVisible()) {
        return;
    }
    if (window()->isMinimized()) {
        m_redrawTimer.start(kMinimizedRetryMs);
        return;
    }
    redraw();
}

void PlotPanel::redraw()
{
    syncCharts();
    m_shownLatest = latestTime();
    const TimeSpan span = m_viewport.range(*m_shownLatest);
    for (StripChart *chart : std::as_const(m_charts)) {
        chart->refresh(*m_store, span, m_autoscale);
    }
    alignStackedCharts();
    m_readout->showValues(*m_store, plottedTraces(), m_cursor);
    m_dirty = false;
    ++m_redraws;
}

StripChart *PlotPanel::addChart()
{
    auto *chart = new StripChart(m_chartArea);
    chart->setMinimumHeight(kMinChartHeight);
    chart->installEventFilter(this);
    connect(chart, &TimeChartView::cursorMoved, this, [this](double t) { setCursorTime(t); });
    connect(chart, &TimeChartView::cursorLeft, this, [this] { setCursorTime(std::nullopt); });
    connect(chart, &TimeChartView::panRequested, this, [this](double seconds) {
        m_viewport.pan(seconds, latestTime());
        viewChanged();
    });
    connect(chart, &TimeChartView::zoomRequested, this, [this](double factor, double anchor) {
        m_viewport.zoom(factor, anchor, latestTime());
        viewChanged();
    });
    connect(chart, &TimeChartView::rangeSelected, this, [this](double t0, double t1) {
        m_viewport.select(t0, t1);
        viewChanged();
    });
    connect(chart, &TimeChartView::valueZoomRequested, this, [this, chart](double factor) {
        setAutoscale(false); // scaling by hand: autoscale would undo it at once
        chart->scaleValueAxes(factor);
    });
    m_chartArea->addWidget(chart);
    m_charts.append(chart);
    return chart;
}

void PlotPanel::syncCharts()
{
    const bool stacked = m_layout == Layout::Stacked;
    const qsizetype wanted = stacked ? std::max<qsizetype>(1, m_channels.size()) : 1;
    while (m_charts.size() > wanted) {
        delete m_charts.takeLast(); // safe: no chart signal (see addChart) leads here
    }
    while (m_charts.size() < wanted) {
        addChart();
    }
    for (qsizetype i = 0; i < m_charts.size(); ++i) {
        StripChart *chart = m_charts.at(i);
        if (stacked) {
            const QVector<PlotTrace> traces =
                i < m_channels.size() ? tracesFor(m_channels.at(i)) : QVector<PlotTrace>{};
            chart->setTraces(traces, StripChart::Coloring::ByDrive);
        } else {
            chart->setTraces(plottedTraces(), StripChart::Coloring::ByChannel);
        }
        chart->setTimeLabelsVisible(i == m_charts.size() - 1);
        chart->setCursorTime(m_cursor);
    }
}

void PlotPanel::alignStackedCharts()
{
    // Padding changes the chart's margins, and QtCharts lays a chart out again on every
    // margin change: it is set only when it changes (setting it to 0 and back at every frame
    // cost a third of the GUI's CPU time while plotting).
    if (m_layout != Layout::Stacked || m_charts.size() < 2) {
        for (StripChart *chart : std::as_const(m_charts)) {
            chart->setAlignmentPadding(0, 0);
        }
        return;
    }
    // Pad each chart to the widest axes so that one time is at the same x in every chart.
    double left = 0, right = 0;
    for (const StripChart *chart : std::as_const(m_charts)) {
        left = std::max(left, chart->axisInsetLeft());
        right = std::max(right, chart->axisInsetRight());
    }
    for (StripChart *chart : std::as_const(m_charts)) {
        chart->setAlignmentPadding(left - chart->axisInsetLeft(), right - chart->axisInsetRight());
    }
}

void PlotPanel::setCursorTime(std::optional<double> time)
{
    m_cursor = time;
    for (StripChart *chart : std::as_const(m_charts)) {
        chart->setCursorTime(time);
    }
    m_readout->showValues(*m_store, plottedTraces(), m_cursor);
}

QMenu *PlotPanel::buildCsvMenu(QWidget *parent)
{
    auto *menu = new QMenu(parent);
    connect(menu->addAction(tr("Visible range…")), &QAction::triggered, this,
            [this] { askExportCsv(ExportScope::VisibleRange); });
    connect(menu->addAction(tr("Everything recorded…")), &QAction::triggered, this,
            [this] { askExportCsv(ExportScope::Everything); });
    // The two layouts of docs/CSV.md, as lkctl monitor --csv-layout offers them.
    menu->addSection(tr("Layout"));
    auto *group = new QActionGroup(menu);
    const auto addLayout = [&](const QString &text, const QString &tip, CsvLayout layout) {
        QAction *a = menu->addAction(text);
        a->setToolTip(tip);
        a->setCheckable(true);
        a->setChecked(layout == m_csvLayout);
        a->setActionGroup(group);
        connect(a, &QAction::toggled, this, [this, layout](bool on) {
            if (on) {
                m_csvLayout = layout;
            }
        });
    };
    addLayout(tr("Wide: one row per poll round"),
              tr("time_s, then a column per drive and signal (id3_speed_dps, ...)"),
              CsvLayout::Wide);
    addLayout(tr("Long: one row per drive and poll round"),
              tr("time_s, id, then a column per signal"), CsvLayout::Long);
    menu->setToolTipsVisible(true);
    return menu;
}

QString PlotPanel::exportCsv(const QString &path, ExportScope scope) const
{
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const TimeSpan span =
        scope == ExportScope::VisibleRange ? visibleRange() : TimeSpan{-kInf, kInf};
    return PlotExporter::exportCsv(*m_store, plottedTraces(), span, path, m_csvLayout);
}

QString PlotPanel::exportPng(const QString &path)
{
    if (m_dirty && isVisible()) {
        redraw(); // the picture shows the data as it is now, not as of the last tick
    }
    return PlotExporter::exportPng(m_chartArea, path);
}

void PlotPanel::askExportCsv(ExportScope scope)
{
    const QString path = FileDialogs::saveFile(
        this, FileDialogs::Purpose::PlotCsv, tr("Export CSV"),
        FileDialogs::suggestedName(QStringLiteral("plot"), m_drives, QDateTime::currentDateTime(),
                                   QStringLiteral("csv")),
        tr("CSV files (*.csv)"));
    if (path.isEmpty()) {
        return;
    }
    if (const QString error = exportCsv(path, scope); !error.isEmpty()) {
        QMessageBox::warning(this, tr("Export CSV"), error);
    }
}

void PlotPanel::askExportPng()
{
    const QString path = FileDialogs::saveFile(
        this, FileDialogs::Purpose::PlotImage, tr("Export PNG"),
        FileDialogs::suggestedName(QStringLiteral("plot"), m_drives, QDateTime::currentDateTime(),
                                   QStringLiteral("png")),
        tr("PNG images (*.png)"));
    if (path.isEmpty()) {
        return;
    }
    if (const QString error = exportPng(path); !error.isEmpty()) {
        QMessageBox::warning(this, tr("Export PNG"), error);
    }
}

} // namespace lk::ui
