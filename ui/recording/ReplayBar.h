#pragma once

#include <QtWidgets/QToolBar>

class QComboBox;
class QLabel;
class QSlider;
class QTimer;
class QToolButton;

namespace lk::ui {

class RecordingReplay;

/// The replay controls: play/pause, speed (0.25x..20x, idle gaps skipped), a seek slider
/// with the position, "Load all" and "Close". Shown while a recording is open.
class ReplayBar : public QToolBar {
    Q_OBJECT
public:
    explicit ReplayBar(RecordingReplay *replay, QWidget *parent = nullptr);

    /// A recording was opened (or closed): show its name and length, or hide.
    void refresh();
    QComboBox *speedCombo() const { return m_speed; }
    QSlider *slider() const { return m_slider; }

signals:
    void closeRequested();

private:
    void update();

    RecordingReplay *m_replay;
    QLabel *m_name = nullptr;
    QToolButton *m_play = nullptr;
    QComboBox *m_speed = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_position = nullptr;
    QTimer *m_timer = nullptr;
};

} // namespace lk::ui
