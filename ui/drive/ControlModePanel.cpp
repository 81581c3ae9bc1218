#include "ControlModePanel.h"

#include <motor/SeriesLimits.h>
#include <protocol/RequestBuilder.h>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QStackedWidget>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr double kRpmToDps = 6.0;
// Wide on purpose: the builders and MotionGuard refuse with a reason, a spin box would clamp.
constexpr double kWideSpeed = 1e7;
constexpr double kWideAngle = 1e9;
constexpr double kWideTorque = 100;
constexpr int kWidePower = 5000;
constexpr double kDefaultMaxSpeedDps = 360;

const ControlMode kAllModes[] = {ControlMode::OpenLoop,       ControlMode::Torque,
                                 ControlMode::Speed,          ControlMode::MultiPosition,
                                 ControlMode::SinglePosition, ControlMode::IncrementPosition};

protocol::Command commandOf(ControlMode mode)
{
    switch (mode) {
    case ControlMode::OpenLoop:
        return protocol::Command::OpenLoop;
    case ControlMode::Torque:
        return protocol::Command::Torque;
    case ControlMode::Speed:
        return protocol::Command::Speed;
    case ControlMode::MultiPosition:
        return protocol::Command::MultiPosition;
    case ControlMode::SinglePosition:
        return protocol::Command::SinglePosition;
    case ControlMode::IncrementPosition:
        return protocol::Command::IncrementPosition;
    }
    return protocol::Command::Speed;
}
} // namespace

ControlModePanel::ControlModePanel(QWidget *parent)
    : QWidget(parent), m_mode(new QComboBox(this)), m_unit(new QComboBox(this)),
      m_pages(new QStackedWidget(this))
{
    m_mode->setObjectName(QStringLiteral("mode"));
    m_unit->setObjectName(QStringLiteral("speedUnit"));
    m_unit->addItem(tr("dps (\u00b0/s)"), int(SpeedUnit::Dps));
    m_unit->addItem(tr("rpm"), int(SpeedUnit::Rpm));
    m_unit->setToolTip(tr("Unit of every speed field; rotor speed, as on the wire."));
    for (ControlMode mode : kAllModes)
        m_pages->addWidget(buildPage(mode));

    auto *top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Mode:"), this));
    top->addWidget(m_mode, 1);
    top->addWidget(new QLabel(tr("Speed unit:"), this));
    top->addWidget(m_unit);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_pages);

    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] {
        const ControlMode m = mode();
        showPage(m);
        emit modeChanged(m);
    });
    connect(m_unit, &QComboBox::currentIndexChanged, this, &ControlModePanel::refreshSpeedSuffixes);
    setSeries(std::nullopt);
    resetInputs();
    refreshSpeedSuffixes();
}

QString ControlModePanel::modeName(ControlMode mode)
{
    switch (mode) {
    case ControlMode::OpenLoop:
        return tr("Open loop power (0xA0)");
    case ControlMode::Torque:
        return tr("Torque current (0xA1)");
    case ControlMode::Speed:
        return tr("Speed (0xA2)");
    case ControlMode::MultiPosition:
        return tr("Multi-turn position (0xA3/0xA4)");
    case ControlMode::SinglePosition:
        return tr("Single-turn position (0xA5/0xA6)");
    case ControlMode::IncrementPosition:
        return tr("Incremental position (0xA7/0xA8)");
    }
    return QString();
}

QDoubleSpinBox *ControlModePanel::number(const QString &name, double lo, double hi, int decimals,
                                         const QString &suffix)
{
    auto *box = new QDoubleSpinBox(this);
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    box->setMinimumWidth(140);
    // Enter in a field sends, as the Send button does.
    connect(box->findChild<QLineEdit *>(), &QLineEdit::returnPressed, this,
            &ControlModePanel::sendRequested);
    return box;
}

QWidget *ControlModePanel::buildPage(ControlMode mode)
{
    switch (mode) {
    case ControlMode::OpenLoop:
        return pageOpenLoop();
    case ControlMode::Torque:
        return pageTorque();
    case ControlMode::Speed:
        return pageSpeed();
    case ControlMode::MultiPosition:
        return pageMulti();
    case ControlMode::SinglePosition:
        return pageSingle();
    case ControlMode::IncrementPosition:
        return pageIncrement();
    }
    return new QWidget(this);
}

QWidget *ControlModePanel::pageOpenLoop()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_power = new QSpinBox(page);
    m_power->setObjectName(QStringLiteral("power"));
    m_power->setRange(-kWidePower, kWidePower);
    m_power->setKeyboardTracking(false);
    connect(m_power->findChild<QLineEdit *>(), &QLineEdit::returnPressed, this,
            &ControlModePanel::sendRequested);
    form->addRow(tr("Power (-850..850):"), m_power); // the stricter bound of V2.3 and V2.35
    auto *note = new QLabel(tr("Not limited by the drive: your open-loop limit applies."), page);
    note->setWordWrap(true);
    form->addRow(note);
    return page;
}

QWidget *ControlModePanel::pageTorque()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_torque = number(QStringLiteral("torqueA"), -kWideTorque, kWideTorque, 2, tr(" A"));
    m_torque->setSingleStep(0.1);
    form->addRow(tr("Torque current iq:"), m_torque);
    auto *note = new QLabel(tr("Not limited by the drive: your torque limit applies."), page);
    note->setWordWrap(true);
    form->addRow(note);
    return page;
}

QWidget *ControlModePanel::pageSpeed()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_speed = number(QStringLiteral("speed"), -kWideSpeed, kWideSpeed, 2, QString());
    m_speed->setSingleStep(10);
    m_speedFields.append(m_speed);
    form->addRow(tr("Speed (sign = direction):"), m_speed);
    return page;
}

ControlModePanel::MaxSpeed ControlModePanel::addMaxSpeed(QWidget *page, QFormLayout *form,
                                                         const QString &name)
{
    MaxSpeed m;
    m.enabled = new QCheckBox(tr("Lower max speed"), page);
    m.enabled->setObjectName(name + QStringLiteral("Limited"));
    m.enabled->setToolTip(tr("Unticked, the move is sent with your speed limit as its max "
                             "speed; tick to give a lower one."));
    m.value = number(name + QStringLiteral("MaxSpeed"), 0, kWideSpeed, 2, QString());
    m.value->setValue(kDefaultMaxSpeedDps);
    m.value->setEnabled(false);
    m_speedFields.append(m.value);
    QDoubleSpinBox *value = m.value;
    connect(m.enabled, &QCheckBox::toggled, value, &QWidget::setEnabled);
    form->addRow(m.enabled, m.value);
    auto *note = new QLabel(tr("Always sent with a max speed (0xA4/0xA6/0xA8): your speed limit "
                               "unless you give a lower one."),
                            page);
    note->setWordWrap(true);
    form->addRow(note);
    return m;
}

QWidget *ControlModePanel::pageMulti()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_multiAngle = number(QStringLiteral("multiAngle"), -kWideAngle, kWideAngle, 2, tr(" \u00b0"));
    // The lowest value stands for "not read yet": a target never defaults to 0 absolute.
    m_multiAngle->setSpecialValueText(tr("reading the drive's angle\u2026"));
    m_multiAngle->setToolTip(tr("Starts at the drive's current angle; at most one output turn "
                                "away."));
    connect(m_multiAngle, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { m_multiTargetSet = v > m_multiAngle->minimum(); });
    form->addRow(tr("Target angle (rotor, multi-turn):"), m_multiAngle);
    m_multiMax = addMaxSpeed(page, form, QStringLiteral("multi"));
    return page;
}

QWidget *ControlModePanel::pageSingle()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_singleAngle = number(QStringLiteral("singleAngle"), -1000, 1000, 2, tr(" \u00b0"));
    m_singleAngle->setToolTip(tr("0..359.99\u00b0 within one rotor turn"));
    m_direction = new QComboBox(page);
    m_direction->setObjectName(QStringLiteral("direction"));
    m_direction->addItem(tr("Clockwise"), int(protocol::SpinDirection::Clockwise));
    m_direction->addItem(tr("Counter-clockwise"), int(protocol::SpinDirection::CounterClockwise));
    form->addRow(tr("Target angle (0..359.99):"), m_singleAngle);
    form->addRow(tr("Direction:"), m_direction);
    m_singleMax = addMaxSpeed(page, form, QStringLiteral("single"));
    return page;
}

QWidget *ControlModePanel::pageIncrement()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_increment = number(QStringLiteral("increment"), -kWideAngle, kWideAngle, 2, tr(" \u00b0"));
    form->addRow(tr("Move by (sign = direction):"), m_increment);
    m_incrementMax = addMaxSpeed(page, form, QStringLiteral("increment"));
    return page;
}

void ControlModePanel::setSeries(std::optional<protocol::Series> series)
{
    const ControlMode previous = m_offered.isEmpty() ? ControlMode::Speed : mode();
    m_series = series;
    m_offered.clear();
    for (ControlMode m : kAllModes) {
        const protocol::Command c = commandOf(m);
        const bool needsSeries = m == ControlMode::OpenLoop || m == ControlMode::Torque;
        if (series ? motor::supports(*series, c) : !needsSeries)
            m_offered.append(m);
    }
    const QSignalBlocker block(m_mode);
    m_mode->clear();
    for (ControlMode m : std::as_const(m_offered))
        m_mode->addItem(modeName(m), int(m));
    const int keep = m_mode->findData(int(previous));
    m_mode->setCurrentIndex(keep >= 0 ? keep : m_mode->findData(int(ControlMode::Speed)));
    showPage(mode());
}

void ControlModePanel::showPage(ControlMode mode)
{
    // Only the current page counts for the size: the box fits the mode shown.
    for (int i = 0; i < m_pages->count(); ++i)
        m_pages->widget(i)->setSizePolicy(
            i == int(mode) ? QSizePolicy::Preferred : QSizePolicy::Ignored,
            i == int(mode) ? QSizePolicy::Preferred : QSizePolicy::Ignored);
    m_pages->setCurrentIndex(int(mode));
    m_pages->updateGeometry();
}

bool ControlModePanel::isOffered(ControlMode mode) const
{
    return m_offered.contains(mode);
}

bool ControlModePanel::setMode(ControlMode mode)
{
    const int index = m_mode->findData(int(mode));
    if (index < 0)
        return false;
    m_mode->setCurrentIndex(index);
    showPage(mode);
    return true;
}

ControlMode ControlModePanel::mode() const
{
    return ControlMode(m_mode->currentData().toInt());
}

void ControlModePanel::setSpeedUnit(SpeedUnit unit)
{
    m_unit->setCurrentIndex(m_unit->findData(int(unit)));
}

ControlModePanel::SpeedUnit ControlModePanel::speedUnit() const
{
    return SpeedUnit(m_unit->currentData().toInt());
}

double ControlModePanel::toDps(double value) const
{
    return speedUnit() == SpeedUnit::Rpm ? value * kRpmToDps : value;
}

void ControlModePanel::refreshSpeedSuffixes()
{
    const QString suffix = speedUnit() == SpeedUnit::Rpm ? tr(" rpm") : tr(" dps");
    for (QDoubleSpinBox *box : std::as_const(m_speedFields))
        box->setSuffix(suffix);
}

std::optional<double> ControlModePanel::MaxSpeed::dps(const ControlModePanel &panel) const
{
    if (!enabled->isChecked())
        return std::nullopt;
    return panel.toDps(value->value());
}

void ControlModePanel::MaxSpeed::set(std::optional<double> speed)
{
    enabled->setChecked(speed.has_value());
    if (speed)
        value->setValue(*speed);
}

void ControlModePanel::setPower(int power)
{
    m_power->setValue(power);
}

void ControlModePanel::setTorqueA(double amps)
{
    m_torque->setValue(amps);
}

void ControlModePanel::setSpeed(double speed)
{
    m_speed->setValue(speed);
}

void ControlModePanel::setMultiAngle(double deg, std::optional<double> maxSpeed)
{
    m_multiAngle->setValue(deg);
    m_multiMax.set(maxSpeed);
}

void ControlModePanel::setSingleAngle(double deg, protocol::SpinDirection direction,
                                      std::optional<double> maxSpeed)
{
    m_singleAngle->setValue(deg);
    m_direction->setCurrentIndex(m_direction->findData(int(direction)));
    m_singleMax.set(maxSpeed);
}

void ControlModePanel::setIncrement(double deg, std::optional<double> maxSpeed)
{
    m_increment->setValue(deg);
    m_incrementMax.set(maxSpeed);
}

void ControlModePanel::resetInputs()
{
    m_power->setValue(0);
    m_torque->setValue(0);
    m_speed->setValue(0);
    m_multiAngle->setValue(m_multiAngle->minimum());
    m_singleAngle->setValue(0);
    m_increment->setValue(0);
    for (MaxSpeed *m : {&m_multiMax, &m_singleMax, &m_incrementMax})
        m->set(std::nullopt);
    m_multiTargetSet = false;
}

protocol::BuildResult ControlModePanel::buildRequest(int id) const
{
    namespace build = protocol::build;
    switch (mode()) {
    case ControlMode::OpenLoop:
        return build::openLoop(id, m_power->value());
    case ControlMode::Torque:
        return build::torque(id, m_torque->value(),
                             {m_series.value_or(protocol::Series::MF), m_generation});
    case ControlMode::Speed:
        return build::speed(id, toDps(m_speed->value()));
    case ControlMode::MultiPosition: {
        const auto max = m_multiMax.dps(*this);
        return max ? build::multiPosition(id, m_multiAngle->value(), *max)
                   : build::multiPosition(id, m_multiAngle->value());
    }
    case ControlMode::SinglePosition: {
        const auto dir = protocol::SpinDirection(m_direction->currentData().toInt());
        const auto max = m_singleMax.dps(*this);
        return max ? build::singlePosition(id, dir, m_singleAngle->value(), *max)
                   : build::singlePosition(id, dir, m_singleAngle->value());
    }
    case ControlMode::IncrementPosition: {
        const auto max = m_incrementMax.dps(*this);
        return max ? build::incrementPosition(id, m_increment->value(), *max)
                   : build::incrementPosition(id, m_increment->value());
    }
    }
    return build::plain(protocol::Command::MotorStop, id);
}

} // namespace lk::ui
