#pragma once

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QVector>
#include <QtWidgets/QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QSpinBox;
class QStackedWidget;

namespace lk::ui {

/// The control modes of protocol V2.3, one input page each.
enum class ControlMode {
    OpenLoop,          ///< 0xA0, MS only: power -1000..1000
    Torque,            ///< 0xA1, MF/MG/MH: iq in A
    Speed,             ///< 0xA2
    MultiPosition,     ///< 0xA3 / 0xA4 with max speed
    SinglePosition,    ///< 0xA5 / 0xA6 with max speed
    IncrementPosition, ///< 0xA7 / 0xA8 with max speed
};

/// Picks a control mode and holds its inputs in physical units (A, power, dps or rpm, deg).
/// Only modes the drive's series implements are offered. Input ranges are deliberately wider
/// than the protocol's, so that an out-of-range value reaches the builder and is refused
/// with its reason instead of being clamped silently.
class ControlModePanel : public QWidget {
    Q_OBJECT
public:
    enum class SpeedUnit { Dps, Rpm };

    explicit ControlModePanel(QWidget *parent = nullptr);

    /// Offers the modes of the series; torque and open loop need a known series.
    void setSeries(std::optional<protocol::Series> series);
    /// The drive's protocol generation: a torque is built at its scale (V2.35 MF and MG differ
    /// from V2.3).
    void setGeneration(protocol::Generation generation) { m_generation = generation; }
    bool isOffered(ControlMode mode) const;
    /// Shows the page of `mode`; false (nothing changes) when it is not offered.
    bool setMode(ControlMode mode);
    ControlMode mode() const;

    void setSpeedUnit(SpeedUnit unit);
    SpeedUnit speedUnit() const;
    /// A speed typed in the current unit, in dps.
    double toDps(double value) const;

    // Inputs (physical units; speeds in the current speed unit).
    void setPower(int power);
    void setTorqueA(double amps);
    void setSpeed(double speed);
    void setMultiAngle(double deg, std::optional<double> maxSpeed = std::nullopt);
    void setSingleAngle(double deg, protocol::SpinDirection direction,
                        std::optional<double> maxSpeed = std::nullopt);
    void setIncrement(double deg, std::optional<double> maxSpeed = std::nullopt);

    /// Every input back to rest (0, no max speed) and the multi-turn target to "not read yet":
    /// a value typed for one drive must not be sent to another.
    void resetInputs();
    /// The multi-turn target was set (typed, or filled from the drive's angle) since the last
    /// resetInputs(); until then it shows "not read yet" and must not be sent.
    bool hasMultiTarget() const { return m_multiTargetSet; }

    /// The request of the current mode and inputs, validated by the protocol builders.
    protocol::BuildResult buildRequest(int id) const;

    static QString modeName(ControlMode mode);

signals:
    /// Enter was pressed in an input: send the command.
    void sendRequested();
    void modeChanged(lk::ui::ControlMode mode);

private:
    /// A position page's optional speed limit.
    struct MaxSpeed {
        QCheckBox *enabled = nullptr;
        QDoubleSpinBox *value = nullptr;
        std::optional<double> dps(const ControlModePanel &panel) const;
        void set(std::optional<double> speed);
    };
    QWidget *buildPage(ControlMode mode);
    void showPage(ControlMode mode);
    QWidget *pageOpenLoop();
    QWidget *pageTorque();
    QWidget *pageSpeed();
    QWidget *pageMulti();
    QWidget *pageSingle();
    QWidget *pageIncrement();
    MaxSpeed addMaxSpeed(QWidget *page, QFormLayout *form, const QString &name);
    QDoubleSpinBox *number(const QString &name, double lo, double hi, int decimals,
                           const QString &suffix);
    void refreshSpeedSuffixes();

    QComboBox *m_mode;
    QComboBox *m_unit;
    QStackedWidget *m_pages;
    QVector<ControlMode> m_offered;
    std::optional<protocol::Series> m_series;
    protocol::Generation m_generation = protocol::Generation::V2_3;
    QSpinBox *m_power = nullptr;
    QDoubleSpinBox *m_torque = nullptr;
    QDoubleSpinBox *m_speed = nullptr;
    QDoubleSpinBox *m_multiAngle = nullptr;
    QDoubleSpinBox *m_singleAngle = nullptr;
    QComboBox *m_direction = nullptr;
    QDoubleSpinBox *m_increment = nullptr;
    MaxSpeed m_multiMax, m_singleMax, m_incrementMax;
    QVector<QDoubleSpinBox *> m_speedFields;
    bool m_multiTargetSet = false;
};

} // namespace lk::ui
