#pragma once

#include <QtWidgets/QGroupBox>

class QCheckBox;
class QDoubleSpinBox;
class QPushButton;

namespace lk::ui {

/// Jog controls: hold-to-run buttons (speed while pressed, stop on release) and step buttons
/// (one incremental move per click), plus the switch that lets arrow keys jog. It only
/// reports what the user does; the control view sends through the motion gate.
class JogPanel : public QGroupBox {
    Q_OBJECT
public:
    explicit JogPanel(QWidget *parent = nullptr);

    double speedDps() const;
    double stepDeg() const;
    void setSpeedDps(double dps);
    void setStepDeg(double deg);
    /// Arrow keys jog (Left/Right hold to run, Down/Up step) while the view has focus and no
    /// text field does. Off by default: a stray key must not move a motor.
    bool keyboardJog() const;
    void setKeyboardJog(bool on);

    QPushButton *holdButton(int direction) const { return direction < 0 ? m_holdNeg : m_holdPos; }
    QPushButton *stepButton(int direction) const { return direction < 0 ? m_stepNeg : m_stepPos; }

signals:
    void holdStarted(int direction); ///< -1 or +1
    void holdEnded();
    void stepRequested(int direction);

private:
    QPushButton *button(const QString &name, const QString &text, const QString &tip);

    QDoubleSpinBox *m_speed;
    QDoubleSpinBox *m_step;
    QCheckBox *m_keys;
    QPushButton *m_holdNeg;
    QPushButton *m_holdPos;
    QPushButton *m_stepNeg;
    QPushButton *m_stepPos;
};

} // namespace lk::ui
