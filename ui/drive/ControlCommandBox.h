#pragma once

#include "ControlModePanel.h"
#include "ParamSetSpec.h"

#include <QtWidgets/QGroupBox>

class QPushButton;

namespace lk::ui {

/// The Control view's command box: the control mode and its inputs (ControlModePanel), Send,
/// and the run-state buttons Motor Off (0x80), Stop (0x81) and Run (0x88). It only asks: the
/// view sends everything through its motion gate.
class ControlCommandBox : public QGroupBox {
    Q_OBJECT
public:
    explicit ControlCommandBox(QWidget *parent = nullptr);

    ControlModePanel *modePanel() const { return m_modes; }
    /// Send and the run-state buttons work only while something can be sent.
    void setSendEnabled(bool enabled);

    /// The loop a plot should show for a control mode: angle for positions, iq for torque.
    static TunedLoop loopOf(ControlMode mode);

signals:
    void sendRequested();
    void motorOffRequested();
    void motorStopRequested();
    void motorRunRequested();
    /// The mode changed: the loop its command moves (loopOf()).
    void loopChanged(lk::ui::TunedLoop loop);

protected:
    void changeEvent(QEvent *event) override;

private:
    QWidget *buildRunButtons();
    void applyPaletteStyles();

    ControlModePanel *m_modes = nullptr;
    QPushButton *m_send = nullptr;
    QPushButton *m_off = nullptr;
    QPushButton *m_stop = nullptr;
    QPushButton *m_run = nullptr;
};

} // namespace lk::ui
