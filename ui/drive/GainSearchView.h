#pragma once

#include <tuning/GainSearchRunner.h>

#include <QtCore/QPointer>
#include <QtWidgets/QWidget>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class BodeChart;
class GainSearchViewComparison;
class StepOverlayChart;
class TuningView;
struct TuningRunDrive;

/// Suggested gains for the Tuning view's drive: a search over the speed loop's Kp and Ki, or
/// the position loop's where an angle window is set (tuning::GainSearchRunner: short speed or
/// position steps within the soft limits, scored on rise time with the overshoot under a bound),
/// the candidates tried as a table and the best beside the gains read (their steps, and optionally
/// their Bode: GainSearchSpec::measureBode). It writes nothing to the drive but the candidates it
/// tries, and puts the gains read back at the end: "Write to RAM" writes the best (through the
/// Tuning view's own write and read-back), and ROM is a separate step behind the Tuning view's
/// confirmation. Esc and the Stop button stop a search at once (Motor Off, the gains read back in
/// RAM).
class GainSearchView : public QWidget {
    Q_OBJECT
public:
    explicit GainSearchView(TuningView *host, QWidget *parent = nullptr);
    ~GainSearchView() override;

    tuning::GainSearchSpec spec() const;
    void setSpec(const tuning::GainSearchSpec &spec);
    /// Checks, asks, then starts the search. False (and says why) when nothing was started.
    bool runSearch();
    /// Stops a running search at once (the emergency stop's first step, Esc, Stop).
    void halt();
    bool isRunning() const;
    /// Writes the best candidate's Kp and Ki of the loop searched to RAM (the Tuning view's
    /// write, read back).
    bool writeBestToRam();
    /// Asks (the Tuning view's ROM confirmation), then writes the gains written to RAM to ROM.
    bool writeBestToRom();
    QString statusText() const;
    QTableWidget *candidates() const { return m_table; }
    /// The step of the gains read beside the best candidate's.
    StepOverlayChart *overlay() const;
    /// The Bode of the gains read beside the best candidate's (when measured).
    BodeChart *bode() const;
    /// The last search's outcome (nullopt before one ended).
    const std::optional<tuning::GainSearchResult> &result() const { return m_result; }
    /// The best candidate's gains (nullopt: none accepted yet).
    std::optional<tuning::LoopGains> best() const;

    static QString verdictText(tuning::CandidateVerdict verdict);
    /// "Speed" or "Angle": the loop whose gains a search of `loop` changes (the gains' names).
    static QString loopGainName(tuning::StepLoop loop);
    static QString riseText(const tuning::CandidateScore &score);
    static QString overshootText(const tuning::CandidateScore &score);

signals:
    void runningChanged(bool running);

protected:
    void showEvent(QShowEvent *event) override;

private:
    QWidget *buildFields();
    tuning::StepLoop loop() const;
    void ensureRunner(bus::BusSession *session);
    void onScored(const tuning::CandidateScore &score, int index);
    void onEnded(const tuning::GainSearchResult &result);
    void onBodeSweep(bool best, double seconds);
    void fillRow(int row, const tuning::CandidateScore &score);
    /// What the search's Bode step adds, in words ("" without a drive or when refused).
    QString bodeTimeText(const TuningRunDrive &drive) const;
    /// The Tuning view's values with the best Kp and Ki of the loop searched; nullopt with `why`.
    std::optional<QVector<qint64>> suggestedValues(QString *why) const;
    void refresh();
    void setStatus(const QString &text, bool error = false);

    TuningView *m_host;
    std::unique_ptr<tuning::GainSearchRunner> m_runner;
    QPointer<bus::BusSession> m_runnerSession;
    std::optional<tuning::GainSearchResult> m_result;
    int m_searchedId = 0;
    bool m_ramWritten = false; ///< the best went to RAM through the Tuning view
    QFormLayout *m_form = nullptr;
    QComboBox *m_loop = nullptr;
    QHBoxLayout *m_speedSteps = nullptr; ///< speed: FROM <-> TO
    QDoubleSpinBox *m_step = nullptr;    ///< position: the steps' size, deg
    QDoubleSpinBox *m_overshoot = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QSpinBox *m_maxCandidates = nullptr;
    QCheckBox *m_measureBode = nullptr;
    QLabel *m_travel = nullptr;
    QPushButton *m_run = nullptr;
    QPushButton *m_writeRam = nullptr;
    QPushButton *m_writeRom = nullptr;
    QTableWidget *m_table = nullptr;
    GainSearchViewComparison *m_compare = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace lk::ui
