#include "DashboardPanel.h"

#include "BusModel.h"
#include "DriveHealth.h"
#include "Format.h"
#include "Readout.h"
#include "SendBlockedTips.h"
#include "StatisticsView.h"
#include "StatusColors.h"
#include "ThemedIcon.h"

#include <drive/EncoderResolutions.h>

#include <QtCore/QTimer>
#include <QtGui/QIcon>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QScrollArea>
#include <QtWidgets/QStackedWidget>
#include <QtWidgets/QVBoxLayout>

#include <cmath>

namespace lk::ui {

namespace {
constexpr int kRefreshMs = 50;           // 20 Hz: smooth for numbers, cheap for the GUI
constexpr double kRpmPerDps = 1.0 / 6.0; // 1 rpm = 6 deg/s
const char kDegree[] = "\u00b0";
using F = bus::TelemetryField;
} // namespace

DashboardPanel::DashboardPanel(BusModel *model, QWidget *parent) : QWidget(parent), m_model(model)
{
    setObjectName(QStringLiteral("dashboard"));
    m_stack = new QStackedWidget(this);
    m_empty = new QLabel(tr("No drive selected. Connect to a bus and scan it; then pick a drive "
                            "in the list on the left."),
                         this);
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->setWordWrap(true);
    m_stack->addWidget(m_empty);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(buildPage());
    m_stack->addWidget(scroll);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_stack);

    m_refresh = new QTimer(this);
    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, &DashboardPanel::refresh);
    m_refresh->start();
    connect(m_model, &BusModel::currentDriveChanged, this, &DashboardPanel::refresh);
    connect(m_model, &BusModel::drivesChanged, this, [this] {
        m_shownId = -1;
        refresh();
    });
    connect(m_model, &BusModel::connectionChanged, this, &DashboardPanel::refresh);
    connect(m_clearErrors, &QPushButton::clicked, this, [this] {
        if (m_model->currentId())
            emit clearErrorsRequested(m_model->currentId());
    });
    refresh();
}

QWidget *DashboardPanel::buildPage()
{
    auto *page = new QWidget(this);
    auto *grid = new QGridLayout(page);
    grid->addWidget(buildIdentity(), 0, 0, 1, 2);
    grid->addWidget(buildElectrical(), 1, 0);
    grid->addWidget(buildMotion(), 1, 1);
    grid->addWidget(buildErrors(), 2, 0);
    m_stats = new StatisticsView(m_model, page);
    grid->addWidget(m_stats, 2, 1);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);
    grid->setRowStretch(3, 1);
    return page;
}

QWidget *DashboardPanel::buildIdentity()
{
    m_identity = new QLabel(this);
    m_identity->setObjectName(QStringLiteral("driveIdentity"));
    m_identity->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_identity->setWordWrap(true);
    QFont f = m_identity->font();
    f.setPointSizeF(f.pointSizeF() * 1.2);
    m_identity->setFont(f);
    return m_identity;
}

Readout *DashboardPanel::makeReadout(const QString &name, const QString &caption, QWidget *parent)
{
    auto *r = new Readout(caption, parent);
    r->setObjectName(name);
    return r;
}

QWidget *DashboardPanel::buildElectrical()
{
    auto *box = new QGroupBox(tr("Electrical"), this);
    auto *grid = new QGridLayout(box);
    grid->addWidget(makeReadout(QStringLiteral("temperature"), tr("Temperature"), box), 0, 0);
    grid->addWidget(makeReadout(QStringLiteral("voltage"), tr("Supply voltage"), box), 0, 1);
    grid->addWidget(makeReadout(QStringLiteral("torque"), tr("Torque current iq"), box), 1, 0, 1,
                    2);
    grid->addWidget(makeReadout(QStringLiteral("phaseA"), tr("Phase A"), box), 2, 0);
    grid->addWidget(makeReadout(QStringLiteral("phaseB"), tr("Phase B"), box), 2, 1);
    grid->addWidget(makeReadout(QStringLiteral("phaseC"), tr("Phase C"), box), 3, 0);
    // Firmware 2.35 and later report these in 0x9A; older drives do not (shown only there).
    grid->addWidget(makeReadout(QStringLiteral("busCurrent"), tr("Bus current"), box), 4, 0);
    grid->addWidget(makeReadout(QStringLiteral("motorState"), tr("Motor"), box), 4, 1);
    return box;
}

QWidget *DashboardPanel::buildMotion()
{
    auto *box = new QGroupBox(tr("Motion"), this);
    auto *grid = new QGridLayout(box);
    grid->addWidget(makeReadout(QStringLiteral("speedDps"), tr("Speed"), box), 0, 0);
    grid->addWidget(makeReadout(QStringLiteral("speedRpm"), tr("Speed"), box), 0, 1);
    grid->addWidget(makeReadout(QStringLiteral("encoder"), tr("Encoder"), box), 1, 0, 1, 2);
    grid->addWidget(makeReadout(QStringLiteral("multiTurn"), tr("Multi-turn angle"), box), 2, 0);
    grid->addWidget(makeReadout(QStringLiteral("singleTurn"), tr("Single-turn angle"), box), 2, 1);
    m_angleNote = new QLabel(box);
    m_angleNote->setObjectName(QStringLiteral("angleNote"));
    m_angleNote->setWordWrap(true);
    grid->addWidget(m_angleNote, 3, 0, 1, 2);
    return box;
}

QWidget *DashboardPanel::buildErrors()
{
    auto *box = new QGroupBox(tr("Error flags"), this);
    auto *layout = new QVBoxLayout(box);
    auto *row = new QHBoxLayout;
    m_errorIcon = new QLabel(box);
    m_errorText = new QLabel(box);
    m_errorText->setObjectName(QStringLiteral("errorFlags"));
    m_errorText->setWordWrap(true);
    QFont f = m_errorText->font();
    f.setPointSizeF(f.pointSizeF() * 1.3);
    f.setBold(true);
    m_errorText->setFont(f);
    row->addWidget(m_errorIcon);
    row->addWidget(m_errorText, 1);
    layout->addLayout(row);
    m_clearErrors = new QPushButton(ThemedIcon::get(QStringLiteral(":/icons/clear.svg")),
                                    tr("Clear Errors"), box);
    m_clearErrors->setObjectName(QStringLiteral("clearErrorsButton"));
    m_clearErrors->setToolTip(tr("Send clear_errors (0x9B). A drive keeps a flag while its cause "
                                 "(low voltage, heat) is still there."));
    layout->addWidget(m_clearErrors, 0, Qt::AlignLeft);
    layout->addStretch(1);
    return box;
}

Readout *DashboardPanel::readout(const QString &name) const
{
    return findChild<Readout *>(name);
}

void DashboardPanel::refresh()
{
    if (!isVisible() && m_shownId == m_model->currentId())
        return; // hidden: nothing to draw; a selection change still updates for the next show
    const DriveRecord *d = m_model->drive(m_model->currentId());
    m_stack->setCurrentIndex(d ? 1 : 0);
    if (!d)
        return;
    const qint64 now = m_model->nowMs();
    if (m_shownId != d->id) {
        m_shownId = d->id;
        updateIdentity(*d);
    }
    updateElectrical(*d, now);
    updateMotion(*d, now);
    updateErrors(*d, now);
    m_clearErrors->setEnabled(m_model->canSend());
    SendBlockedTips::applyTo(m_clearErrors,
                             m_model->isListening() ? m_model->sendBlockedReason() : QString());
}

void DashboardPanel::updateIdentity(const DriveRecord &d)
{
    QStringList parts;
    parts << QStringLiteral("<b>%1</b>").arg(tr("Drive %1").arg(d.id));
    if (d.model) {
        parts << d.model->motorName.toHtmlEscaped();
        parts << tr("driver %1").arg(d.model->driverName.toHtmlEscaped());
    }
    parts << tr("series %1").arg(d.seriesText());
    if (d.model)
        parts << tr("firmware %1, hardware %2").arg(d.firmwareText(), d.hardwareText());
    m_identity->setText(parts.join(QStringLiteral(" \u00b7 ")));

    const auto ratio = d.gearRatio();
    auto *torque = readout(QStringLiteral("torque"));
    torque->setCaption(!d.series          ? tr("Torque current or power (series unknown)")
                       : d.reportsPower() ? tr("Power (relative, MS)")
                                          : tr("Torque current iq"));
    // An MS drive reports power where the others report iq: unknown, it is neither shown.
    torque->setToolTip(d.series ? QString()
                                : tr("No model reply told this drive's series: an MS drive "
                                     "reports power here, the others current. Choose the "
                                     "series in the Bus panel."));
    const QString shaft = ratio ? tr("output shaft") : tr("rotor");
    readout(QStringLiteral("multiTurn"))->setCaption(tr("Multi-turn angle (%1)").arg(shaft));
    readout(QStringLiteral("singleTurn"))->setCaption(tr("Single-turn angle (%1)").arg(shaft));
    readout(QStringLiteral("speedDps"))->setCaption(tr("Speed (%1)").arg(shaft));
    readout(QStringLiteral("speedRpm"))->setCaption(tr("Speed (%1)").arg(shaft));
    m_angleNote->setText(
        ratio ? tr("Gear ratio %1:1 from the motor name: angles and speeds are shown at the output "
                   "shaft; hover for rotor values.")
                    .arg(Format::number(*ratio, ratio == std::floor(*ratio) ? 0 : 2))
              : tr("The motor name gives no gear ratio: angles and speeds are rotor values."));
}

void DashboardPanel::updateElectrical(const DriveRecord &d, qint64 now)
{
    const auto &v = d.latest;
    auto *temp = readout(QStringLiteral("temperature"));
    temp->setValue(d.has(F::Temperature)
                       ? Format::withUnit(v.temperatureC, 0, QStringLiteral("\u00b0C"))
                       : QString(),
                   d.isStale(F::Temperature, now));
    const DriveHealth health = DriveHealth::of(d);
    temp->setAlarm(health.hot);
    temp->setToolTip(tr("Shown red from %1 °C").arg(DriveHealth::kHotTemperatureC));
    const bool v235 = d.generation() == protocol::Generation::V2_35;
    auto *voltage = readout(QStringLiteral("voltage"));
    voltage->setValue(d.has(F::Voltage)
                          ? Format::withUnit(v.voltageV, v235 ? 2 : 1, QStringLiteral("V"))
                          : QString(),
                      d.isStale(F::Voltage, now));
    voltage->setAlarm(health.voltageOut());
    const std::optional<QString> range = DriveHealth::supplyRangeText(d);
    voltage->setToolTip(range ? tr("Shown red outside %1").arg(*range) : QString());
    updateV235State(d, now);
    auto *torque = readout(QStringLiteral("torque"));
    if (!d.series)
        torque->setValue(QString(), false);
    else if (d.reportsPower())
        torque->setValue(d.has(F::Power) ? Format::power(v.power) : QString(),
                         d.isStale(F::Power, now));
    else
        torque->setValue(d.has(F::IqA) ? Format::withUnit(v.iqA, 2, QStringLiteral("A"))
                                       : QString(),
                         d.isStale(F::IqA, now));
    const bool phases = d.hasPhaseCurrents();
    const bool stale = d.isStale(F::PhaseCurrents, now);
    const double amps[] = {v.iaA, v.ibA, v.icA};
    const char *names[] = {"phaseA", "phaseB", "phaseC"};
    for (int i = 0; i < 3; ++i) {
        auto *r = readout(QLatin1String(names[i]));
        if (!phases)
            r->setValue(tr("not on MS"), true);
        else
            r->setValue(d.has(F::PhaseCurrents) ? Format::withUnit(amps[i], 2, QStringLiteral("A"))
                                                : QString(),
                        stale);
    }
}

void DashboardPanel::updateV235State(const DriveRecord &d, qint64 now)
{
    const bool v235 = d.generation() == protocol::Generation::V2_35;
    auto *current = readout(QStringLiteral("busCurrent"));
    auto *state = readout(QStringLiteral("motorState"));
    current->setVisible(v235);
    state->setVisible(v235);
    if (!v235)
        return;
    const auto &v = d.latest;
    current->setValue(d.has(F::BusCurrent) ? Format::withUnit(v.busCurrentA, 2, QStringLiteral("A"))
                                           : QString(),
                      d.isStale(F::BusCurrent, now));
    state->setValue(d.has(F::MotorOn) ? (v.motorOn ? tr("on") : tr("off")) : QString(),
                    d.isStale(F::MotorOn, now));
}

void DashboardPanel::updateMotion(const DriveRecord &d, qint64 now)
{
    const auto &v = d.latest;
    const double ratio = d.gearRatio().value_or(1.0);
    const QString deg = QString::fromUtf8(kDegree);
    auto angle = [&](const QString &name, F field, double rotorDeg) {
        auto *r = readout(name);
        r->setValue(d.has(field) ? Format::withUnit(rotorDeg / ratio, 2, deg) : QString(),
                    d.isStale(field, now));
        r->setToolTip(d.has(field) ? tr("Rotor: %1").arg(Format::withUnit(rotorDeg, 2, deg))
                                   : QString());
    };
    const bool speedStale = d.isStale(F::Speed, now);
    const bool hasSpeed = d.has(F::Speed);
    readout(QStringLiteral("speedDps"))
        ->setValue(hasSpeed ? Format::withUnit(v.speedDps / ratio, 0, QStringLiteral("dps"))
                            : QString(),
                   speedStale);
    readout(QStringLiteral("speedRpm"))
        ->setValue(hasSpeed
                       ? Format::withUnit(v.speedDps * kRpmPerDps / ratio, 1, QStringLiteral("rpm"))
                       : QString(),
                   speedStale);
    readout(QStringLiteral("encoder"))
        ->setValue(d.has(F::Encoder) ? encoderText(d) : QString(), d.isStale(F::Encoder, now));
    angle(QStringLiteral("multiTurn"), F::MultiTurn, v.multiTurnDeg);
    angle(QStringLiteral("singleTurn"), F::SingleTurn, v.singleTurnDeg);
}

void DashboardPanel::setEncoderResolutions(EncoderResolutions *resolutions)
{
    m_resolutions = resolutions;
    refresh();
}

QString DashboardPanel::encoderText(const DriveRecord &d) const
{
    if (!m_resolutions)
        return EncoderResolutions::readoutText(
            d.latest.encoder, motor::EncoderResolution::fromModel(d.nameInfo, d.series));
    bus::KnownMotor motor;
    motor.id = d.id;
    motor.series = d.series;
    motor.model = d.model;
    if (d.model)
        motor.generation = d.model->generation;
    return EncoderResolutions::readoutText(d.latest.encoder, m_resolutions->of(d.id, motor));
}

void DashboardPanel::updateErrors(const DriveRecord &d, qint64 now)
{
    const bool known = d.has(F::ErrorState);
    const int state = known ? d.latest.errorState : 0;
    const bool bad = state != 0;
    QString text = known ? Format::errorFlagsText(state, d.generation()) : tr("Not read yet");
    if (known && d.isStale(F::ErrorState, now))
        text += QLatin1Char(' ') + tr("(no update for over a second)");
    m_errorText->setText(text);
    QPalette p = m_errorText->palette();
    p.setColor(QPalette::WindowText, bad ? StatusColors::text(StatusColors::Role::Error, palette())
                                         : palette().color(QPalette::WindowText));
    m_errorText->setPalette(p);
    // Rendered only when it changes (an SVG render at every refresh cost more than the rest
    // of the dashboard together).
    // The light or dark variant is part of the key: a palette switch renders it again.
    const QString icon = ThemedIcon::pathFor(
        bad ? QStringLiteral(":/icons/error.svg") : QStringLiteral(":/icons/ok.svg"), palette());
    if (m_errorIcon->property("iconPath").toString() != icon) {
        m_errorIcon->setProperty("iconPath", icon);
        m_errorIcon->setPixmap(QIcon(icon).pixmap(32, 32));
    }
}

} // namespace lk::ui
