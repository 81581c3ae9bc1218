#include "JogPanel.h"

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

namespace lk::ui {

namespace {
constexpr double kDefaultSpeedDps = 90;
constexpr double kDefaultStepDeg = 10;
constexpr double kMaxField = 1e6;
} // namespace

JogPanel::JogPanel(QWidget *parent) : QGroupBox(tr("Jog"), parent)
{
    setObjectName(QStringLiteral("jog"));
    m_speed = new QDoubleSpinBox(this);
    m_speed->setObjectName(QStringLiteral("jogSpeed"));
    m_speed->setRange(0, kMaxField);
    m_speed->setDecimals(1);
    m_speed->setSuffix(tr(" dps"));
    m_speed->setValue(kDefaultSpeedDps);
    m_step = new QDoubleSpinBox(this);
    m_step->setObjectName(QStringLiteral("jogStep"));
    m_step->setRange(0, kMaxField);
    m_step->setDecimals(2);
    m_step->setSuffix(tr(" \u00b0"));
    m_step->setValue(kDefaultStepDeg);
    m_keys = new QCheckBox(tr("Arrow keys jog (\u2190 \u2192 hold, \u2193 \u2191 step)"), this);
    m_keys->setObjectName(QStringLiteral("keyboardJog"));
    m_keys->setToolTip(tr("Only while this view has the focus and no text field does."));

    m_holdNeg = button(QStringLiteral("holdNeg"), tr("\u25c0 Hold"),
                       tr("Runs counter-clockwise at the jog speed while pressed"));
    m_holdPos = button(QStringLiteral("holdPos"), tr("Hold \u25b6"),
                       tr("Runs clockwise at the jog speed while pressed"));
    m_stepNeg = button(QStringLiteral("stepNeg"), tr("\u2212 Step"),
                       tr("One incremental move counter-clockwise"));
    m_stepPos =
        button(QStringLiteral("stepPos"), tr("Step +"), tr("One incremental move clockwise"));
    connect(m_holdNeg, &QPushButton::pressed, this, [this] { emit holdStarted(-1); });
    connect(m_holdPos, &QPushButton::pressed, this, [this] { emit holdStarted(+1); });
    connect(m_holdNeg, &QPushButton::released, this, &JogPanel::holdEnded);
    connect(m_holdPos, &QPushButton::released, this, &JogPanel::holdEnded);
    connect(m_stepNeg, &QPushButton::clicked, this, [this] { emit stepRequested(-1); });
    connect(m_stepPos, &QPushButton::clicked, this, [this] { emit stepRequested(+1); });

    auto *grid = new QGridLayout(this);
    grid->addWidget(new QLabel(tr("Speed:"), this), 0, 0);
    grid->addWidget(m_speed, 0, 1);
    grid->addWidget(m_holdNeg, 0, 2);
    grid->addWidget(m_holdPos, 0, 3);
    grid->addWidget(new QLabel(tr("Step:"), this), 1, 0);
    grid->addWidget(m_step, 1, 1);
    grid->addWidget(m_stepNeg, 1, 2);
    grid->addWidget(m_stepPos, 1, 3);
    grid->addWidget(m_keys, 2, 0, 1, 4);
    grid->setColumnStretch(1, 1);
}

QPushButton *JogPanel::button(const QString &name, const QString &text, const QString &tip)
{
    auto *b = new QPushButton(text, this);
    b->setObjectName(name);
    b->setToolTip(tip);
    b->setAutoRepeat(false);
    b->setFocusPolicy(Qt::TabFocus); // a click leaves the keyboard focus where it was
    return b;
}

double JogPanel::speedDps() const
{
    return m_speed->value();
}

double JogPanel::stepDeg() const
{
    return m_step->value();
}

void JogPanel::setSpeedDps(double dps)
{
    m_speed->setValue(dps);
}

void JogPanel::setStepDeg(double deg)
{
    m_step->setValue(deg);
}

bool JogPanel::keyboardJog() const
{
    return m_keys->isChecked();
}

void JogPanel::setKeyboardJog(bool on)
{
    m_keys->setChecked(on);
}

} // namespace lk::ui
