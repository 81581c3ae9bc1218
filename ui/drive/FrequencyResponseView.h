#pragma once

#include <tuning/FrequencySweepRunner.h>

#include <QtCore/QPointer>
#include <QtWidgets/QWidget>

#include <memory>

class QComboBox;
class QVBoxLayout;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class BodeChart;
struct TuningRunDrive;
class FrequencyRunList;
class TuningView;

/// The speed or position loop's frequency response of the Tuning view's drive: a stepped sine
/// of the speed setpoint around an operating point, or of the angle around where the drive is
/// (offered only while an angle window is set), from tuning::FrequencySweepRunner (the setpoint
/// stream on the bus thread), its extremes checked against the soft limits before anything
/// moves. The chart overlays the runs of the loop chosen (the same loop and unit) only.
/// Says how far the axis turns and asks first that it is free to; nothing runs unless the
/// drive's gains were read on this connection. Each sweep is kept and overlaid on the Bode
/// chart with its figures. While it runs, its button and Esc stop it at once: the stream
/// halts, Motor Off goes out and the gains read go back to RAM.
class FrequencyResponseView : public QWidget {
    Q_OBJECT
public:
    explicit FrequencyResponseView(TuningView *host, QWidget *parent = nullptr);
    ~FrequencyResponseView() override;

    tuning::FrequencySweepSpec spec() const;
    void setSpec(const tuning::FrequencySweepSpec &spec);
    /// Checks, asks, then starts the sweep the fields describe. False (and says why) when
    /// nothing was started.
    bool runSweep();
    /// Stops a running sweep at once (the emergency stop's first step, Esc, the Stop button).
    void halt();
    bool isRunning() const;
    QString statusText() const;
    /// How far the axis would turn for the fields as set (empty without a drive).
    QString travelText() const;
    tuning::SweepLoop loop() const;
    /// Chooses the loop; false when it is not offered (Position without an angle window).
    bool setLoop(tuning::SweepLoop loop);
    bool positionOffered() const;
    FrequencyRunList *runs() const { return m_runs; }
    /// Saves the run `key` (FrequencyRunFile); false with the status saying why.
    bool saveRun(int key, const QString &path);
    /// Adds the run saved in `path` to the overlay; false with the status naming the bad key.
    bool openRun(const QString &path);
    /// The run chosen in the run picker (0: none).
    int chosenRun() const;
    /// The legend's text of a run: its title, drive, loop, gains and date.
    QString legendText(int key) const;
    BodeChart *chart() const { return m_chart; }

signals:
    void runningChanged(bool running);

protected:
    void showEvent(QShowEvent *event) override;

private:
    QWidget *buildFields();
    QVBoxLayout *buildRunButtons();
    void refreshRunPick();
    void ensureRunner(bus::BusSession *session);
    void onFinished(const tuning::FrequencySweepResult &result);
    void onFailed(const tuning::FrequencySweepResult &result);
    void refreshChart();
    void refresh();
    void onLoopChosen();
    static tuning::FrequencySweepPlan planFor(const tuning::FrequencySweepSpec &spec,
                                              const TuningRunDrive &drive);
    QString refusedText(const tuning::FrequencySweepSpec &spec, double value,
                        const safety::Verdict &verdict) const;
    void setStatus(const QString &text, bool error = false);

    TuningView *m_host;
    FrequencyRunList *m_runs;
    BodeChart *m_chart = nullptr;
    std::unique_ptr<tuning::FrequencySweepRunner> m_runner;
    QPointer<bus::BusSession> m_runnerSession;
    QString m_runningModel;
    QComboBox *m_loop = nullptr;
    QDoubleSpinBox *m_centre = nullptr;
    QDoubleSpinBox *m_amplitude = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QSpinBox *m_points = nullptr;
    QDoubleSpinBox *m_perPoint = nullptr;
    QLabel *m_travel = nullptr;
    QPushButton *m_run = nullptr;
    QPushButton *m_clear = nullptr;
    QComboBox *m_runPick = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_open = nullptr;
    QPushButton *m_remove = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace lk::ui
