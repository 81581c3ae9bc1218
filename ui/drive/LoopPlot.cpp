#include "LoopPlot.h"

#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>

#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr qsizetype kOwnCapacity = 120000; // two minutes at 1 kHz is plenty for tuning
constexpr int kMinChartHeight = 220;

TelemetryChannel channelFor(TunedLoop loop)
{
    switch (loop) {
    case TunedLoop::Angle:
        return TelemetryChannel::MultiTurn;
    case TunedLoop::Current:
        return TelemetryChannel::Torque;
    case TunedLoop::Speed:
        break;
    }
    return TelemetryChannel::Speed;
}
} // namespace

LoopPlot::LoopPlot(QWidget *parent)
    : QWidget(parent), m_ownStore(new TelemetryStore(kOwnCapacity, this)), m_store(m_ownStore),
      m_chart(new StripChart(this)), m_loopCombo(new QComboBox(this)), m_hint(new QLabel(this))
{
    m_loopCombo->setObjectName(QStringLiteral("plotLoop"));
    m_loopCombo->addItem(tr("Angle loop: multi-turn angle"), int(TunedLoop::Angle));
    m_loopCombo->addItem(tr("Speed loop: speed"), int(TunedLoop::Speed));
    m_loopCombo->addItem(tr("Current loop: iq (power on MS)"), int(TunedLoop::Current));
    m_loopCombo->setCurrentIndex(1);
    m_loopCombo->setToolTip(tr("Follows the field you edit; pick another loop here."));
    connect(m_loopCombo, &QComboBox::currentIndexChanged, this,
            [this] { setLoop(TunedLoop(m_loopCombo->currentData().toInt())); });

    m_hint->setWordWrap(true);
    m_hint->setObjectName(QStringLiteral("plotHint"));
    m_chart->setMinimumHeight(kMinChartHeight);

    auto *top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Live plot:"), this));
    top->addWidget(m_loopCombo, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_chart, 1);
    layout->addWidget(m_hint);

    m_timer.setInterval(kRedrawIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &LoopPlot::onTimer);
    rebuildTraces();
}

LoopPlot::~LoopPlot() = default;

void LoopPlot::setStore(TelemetryStore *store)
{
    m_store = store ? store : m_ownStore;
    m_drawnRevision = ~quint64(0);
}

TelemetryStore *LoopPlot::store() const
{
    return m_store ? m_store.data() : m_ownStore;
}

bool LoopPlot::ownsStore() const
{
    return store() == m_ownStore;
}

void LoopPlot::appendTelemetry(const bus::TelemetryBatch &batch)
{
    if (ownsStore())
        m_ownStore->append(batch);
}

void LoopPlot::setDrive(int id, bool reportsPower)
{
    if (m_id == id && m_power == reportsPower)
        return;
    m_id = id;
    m_power = reportsPower;
    rebuildTraces();
}

void LoopPlot::setLoop(TunedLoop loop)
{
    if (m_loop == loop)
        return;
    m_loop = loop;
    {
        const QSignalBlocker block(m_loopCombo);
        m_loopCombo->setCurrentIndex(m_loopCombo->findData(int(loop)));
    }
    rebuildTraces();
}

void LoopPlot::rebuildTraces()
{
    QVector<PlotTrace> traces;
    if (m_id > 0)
        traces.append(PlotTrace{m_id, channelFor(m_loop), m_power});
    m_chart->setTraces(traces, StripChart::Coloring::ByChannel);
    m_drawnRevision = ~quint64(0);
    if (isVisible())
        redraw();
}

void LoopPlot::redraw()
{
    TelemetryStore *s = store();
    const SampleRing *ring = m_id > 0 ? s->ring(m_id, channelFor(m_loop)) : nullptr;
    const bool hasData = ring && !ring->isEmpty();
    if (m_id <= 0)
        m_hint->setText(tr("Select a drive to see its loop."));
    else if (!hasData)
        m_hint->setText(tr("No samples of this signal yet: the plot shows what the bus polls "
                           "for drive %1 (polling runs while connected).")
                            .arg(m_id));
    else
        m_hint->setText(
            tr("Last %1 s of drive %2, rotor values.").arg(kDefaultWindowSeconds).arg(m_id));
    const double end = hasData ? ring->timeAt(ring->size() - 1) : kDefaultWindowSeconds;
    m_chart->setMarkers(m_marks.value(m_id));
    refreshChart(TimeSpan{end - kDefaultWindowSeconds, end});
    m_drawnRevision = s->revision();
    ++m_redraws;
}

void LoopPlot::markChange(const QString &label)
{
    const std::optional<TimeSpan> span = store()->timeSpan();
    if (m_id <= 0 || !span)
        return;
    QVector<TimeMarker> &marks = m_marks[m_id];
    marks.append({span->end, label});
    if (marks.size() > kMaxMarks)
        marks.removeFirst();
    redraw();
}

void LoopPlot::refreshChart(TimeSpan span)
{
    // StripChart::refresh sets an axis range before its tick interval. With dynamic ticks a
    // jump from a flat signal's tiny range (motor at rest) to a real one would first lay out
    // millions of ticks at the old interval and freeze the GUI. Fixed ticks during the range
    // change are cheap; refresh sets dynamic ticks at the new interval on the axes it
    // rescales, and the others get their own dynamic ticks back.
    QList<QValueAxis *> fixed;
    for (QAbstractAxis *axis : m_chart->chart()->axes()) {
        auto *value = qobject_cast<QValueAxis *>(axis);
        if (value && value->tickType() == QValueAxis::TicksDynamic) {
            value->setTickType(QValueAxis::TicksFixed);
            fixed.append(value);
        }
    }
    m_chart->refresh(*store(), span, true);
    for (QValueAxis *value : std::as_const(fixed)) {
        if (value->tickType() == QValueAxis::TicksFixed)
            value->setTickType(QValueAxis::TicksDynamic);
    }
}

void LoopPlot::onTimer()
{
    if (store()->revision() != m_drawnRevision)
        redraw();
}

void LoopPlot::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    m_timer.start();
    redraw();
}

void LoopPlot::hideEvent(QHideEvent *event)
{
    m_timer.stop();
    QWidget::hideEvent(event);
}

} // namespace lk::ui
