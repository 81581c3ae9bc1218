#pragma once

#include "ParamSetSpec.h"

#include <plot/TelemetryStore.h>

#include <bus/TelemetrySample.h>

#include <plot/StripChart.h>

#include <QtCore/QHash>
#include <QtCore/QPointer>
#include <QtCore/QTimer>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;

namespace lk::ui {

/// Live plot of the loop being tuned: multi-turn angle for the angle loop, speed for the
/// speed loop, iq (power on MS) for the current loop, over the last seconds. It reads a
/// TelemetryStore (lkstudio's shared one, or its own fed by appendTelemetry) and redraws on
/// a timer while visible, only when something changed.
class LoopPlot : public QWidget {
    Q_OBJECT
public:
    static constexpr int kRedrawIntervalMs = 33;
    static constexpr double kDefaultWindowSeconds = 10;
    static constexpr int kMaxMarks = 32;

    explicit LoopPlot(QWidget *parent = nullptr);
    ~LoopPlot() override;

    /// Read this store (not owned, must outlive the plot); nullptr: use an own store.
    void setStore(TelemetryStore *store);
    TelemetryStore *store() const;
    bool ownsStore() const;
    /// Feed the own store (ignored while reading an external one, which is fed elsewhere).
    void appendTelemetry(const lk::bus::TelemetryBatch &batch);

    void setDrive(int id, bool reportsPower);
    void setLoop(TunedLoop loop);
    TunedLoop loop() const { return m_loop; }
    StripChart *chart() const { return m_chart; }
    quint64 redrawCount() const { return m_redraws; }
    /// Redraw now (tests, screenshots).
    void redraw();
    /// Marks "now" (the newest sample of the shown drive) with `label` on that drive's plot:
    /// a gain change, so its effect can be read off the trace. Nothing without samples.
    void markChange(const QString &label);
    /// The marks of drive `id`, oldest first.
    QVector<TimeMarker> marks(int id) const { return m_marks.value(id); }

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void rebuildTraces();
    void refreshChart(TimeSpan span);
    void onTimer();

    TelemetryStore *m_ownStore;
    QPointer<TelemetryStore> m_store;
    StripChart *m_chart;
    QComboBox *m_loopCombo;
    QLabel *m_hint;
    QTimer m_timer;
    int m_id = 0;
    QHash<int, QVector<TimeMarker>> m_marks; ///< per drive, at most kMaxMarks
    bool m_power = false;
    TunedLoop m_loop = TunedLoop::Speed;
    quint64 m_drawnRevision = ~quint64(0);
    quint64 m_redraws = 0;
};

} // namespace lk::ui
