#pragma once

#include "ControlModePanel.h"
#include "ParamSetSpec.h"

#include <QtWidgets/QGroupBox>

class QLabel;
class QPushButton;

namespace lk::ui {

class DriveStateCheck;

/// The Control view's command box: the control mode and its inputs (ControlModePanel), Send,
/// the run-state buttons Motor Off (0x80), Stop (0x81) and Run (0x88; Motor On on a V2.35
/// drive), and a V2.35 drive's own state (motor on, brake, its own limits). It only asks: the
/// view sends everything through its motion gate.
class ControlCommandBox : public QGroupBox {
    Q_OBJECT
public:
    explicit ControlCommandBox(QWidget *parent = nullptr);

    ControlModePanel *modePanel() const { return m_modes; }
    /// Send and the run-state buttons work only while something can be sent.
    void setSendEnabled(bool enabled);
    /// With several drives selected in lkstudio (`selected` > 1) the box says that it acts
    /// on the one named `driveTitle` only.
    void setSelection(int selected, const QString &driveTitle);
    /// On a V2.35 drive 0x88 turns a motor that is off on: Run is offered as Motor On.
    void setGeneration(protocol::Generation generation);
    /// The drive's own state above the buttons, and `limits` (the drive's own limits) under
    /// it; hidden when neither says anything. Off (Motor On first) shows in the error colour,
    /// an engaged brake in the warning colour.
    void showDriveState(const DriveStateCheck &state, const QString &limits);
    QString driveStateText() const;

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
    QPushButton *m_motorOff = nullptr;
    QPushButton *m_stop = nullptr;
    QPushButton *m_run = nullptr;
    QLabel *m_selection = nullptr;
    QLabel *m_driveState = nullptr;
    bool m_off = false;
    bool m_held = false;
};

} // namespace lk::ui
