#include "ParameterTable.h"

#include <panels/StatusColors.h>

#include <QtCore/QEvent>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QStyle>

#include <limits>

namespace lk::ui {

namespace {
constexpr int kGainMax = 255;
const char kChangedProperty[] = "changed";

qint64 gainOf(const protocol::PidGains &p, int row)
{
    const quint8 values[] = {p.angleKp, p.angleKi, p.speedKp, p.speedKi, p.iqKp, p.iqKi};
    return values[row];
}

QString dash()
{
    return QStringLiteral("\u2013");
}

// An edit field's value while the pending edit is unknown: below every real value, shown as
// the special value text.
constexpr int kUnknown = -1;

int maximumOf(ParameterTable::Row row)
{
    return row == ParameterTable::Accel ? std::numeric_limits<qint32>::max() : kGainMax;
}
} // namespace

ParameterTable::ParameterTable(QWidget *parent) : QWidget(parent), m_rows(kRowCount)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(12);
    const QString headers[] = {tr("Parameter"), tr("First read"), tr("Drive holds"),
                               tr("Pending edit")};
    for (int c = 0; c < 4; ++c) {
        auto *h = new QLabel(QStringLiteral("<b>%1</b>").arg(headers[c].toHtmlEscaped()), this);
        grid->addWidget(h, 0, c);
    }
    const QString names[] = {tr("Angle loop Kp"), tr("Angle loop Ki"),   tr("Speed loop Kp"),
                             tr("Speed loop Ki"), tr("Current loop Kp"), tr("Current loop Ki"),
                             tr("Acceleration")};
    int gridRow = 1;
    for (int r = 0; r < kRowCount; ++r) {
        buildRow(Row(r), names[r], gridRow++);
    }
    grid->setColumnStretch(4, 1);
    applyChangedStyle();
}

void ParameterTable::buildRow(Row row, const QString &name, int gridRow)
{
    auto *grid = static_cast<QGridLayout *>(layout());
    RowWidgets &w = m_rows[row];
    w.name = new QLabel(name, this);
    w.original = new QLabel(dash(), this);
    w.holds = new QLabel(tr("unknown"), this);
    w.edit = new QSpinBox(this);
    w.edit->setObjectName(QStringLiteral("pending_") + rowKey(row));
    w.holds->setObjectName(QStringLiteral("holds_") + rowKey(row));
    w.original->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    w.holds->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    w.edit->setRange(kUnknown, maximumOf(row));
    w.edit->setValue(kUnknown);
    w.edit->setSpecialValueText(tr("unknown"));
    w.edit->setEnabled(false);
    if (row == Accel) {
        w.edit->setSuffix(tr(" dps/s"));
        w.edit->setSingleStep(1000);
        w.edit->setToolTip(tr("0x34 writes acceleration to RAM only: protocol V2.3 has no ROM "
                              "command for it. Some firmware ignores it (read back shows)."));
    } else {
        w.edit->setToolTip(tr("0..255"));
    }
    w.edit->setKeyboardTracking(false);
    w.edit->installEventFilter(this);
    connect(w.edit, &QSpinBox::valueChanged, this, [this] {
        refreshHighlight();
        emit edited();
    });
    grid->addWidget(w.name, gridRow, 0);
    grid->addWidget(w.original, gridRow, 1);
    grid->addWidget(w.holds, gridRow, 2);
    grid->addWidget(w.edit, gridRow, 3);
}

QString ParameterTable::rowKey(Row row)
{
    static const char *keys[] = {"angle_kp", "angle_ki", "speed_kp",  "speed_ki",
                                 "iq_kp",    "iq_ki",    "accel_dps2"};
    return QLatin1String(keys[row]);
}

TunedLoop ParameterTable::loopOf(Row row)
{
    switch (row) {
    case AngleKp:
    case AngleKi:
        return TunedLoop::Angle;
    case IqKp:
    case IqKi:
        return TunedLoop::Current;
    default:
        return TunedLoop::Speed; // acceleration shapes the speed ramp
    }
}

void ParameterTable::setHolds(const std::optional<protocol::PidGains> &pid,
                              const std::optional<qint32> &accelDps2)
{
    for (int r = 0; r < kRowCount; ++r) {
        std::optional<qint64> v;
        if (r == Accel && accelDps2)
            v = *accelDps2;
        else if (r != Accel && pid)
            v = gainOf(*pid, r);
        m_rows[r].holdsValue = v;
        m_rows[r].holds->setText(v ? QString::number(*v) : tr("unknown"));
    }
    refreshHighlight();
}

void ParameterTable::setOriginal(const std::optional<TuningValues> &values)
{
    for (int r = 0; r < kRowCount; ++r) {
        QString text = dash();
        if (values)
            text = QString::number(r == Accel ? qint64(values->accelDps2) : gainOf(values->pid, r));
        m_rows[r].original->setText(text);
    }
}

void ParameterTable::setPending(const TuningValues &values)
{
    m_pendingKnown = true;
    for (int r = 0; r < kRowCount; ++r) {
        QSignalBlocker block(m_rows[r].edit);
        m_rows[r].edit->setMinimum(0);
        m_rows[r].edit->setValue(r == Accel ? values.accelDps2 : int(gainOf(values.pid, r)));
    }
    refreshHighlight();
}

void ParameterTable::clearPending()
{
    m_pendingKnown = false;
    for (int r = 0; r < kRowCount; ++r) {
        QSignalBlocker block(m_rows[r].edit);
        m_rows[r].edit->setMinimum(kUnknown);
        m_rows[r].edit->setValue(kUnknown);
    }
    setEditable(false);
    refreshHighlight();
}

void ParameterTable::setEditable(bool editable)
{
    for (const RowWidgets &w : std::as_const(m_rows))
        w.edit->setEnabled(editable && m_pendingKnown);
}

std::optional<TuningValues> ParameterTable::pending() const
{
    if (!m_pendingKnown)
        return std::nullopt;
    auto v = [this](Row r) { return static_cast<quint8>(m_rows.at(r).edit->value()); };
    TuningValues values;
    values.pid =
        protocol::PidGains{v(AngleKp), v(AngleKi), v(SpeedKp), v(SpeedKi), v(IqKp), v(IqKi)};
    values.accelDps2 = m_rows.at(Accel).edit->value();
    return values;
}

bool ParameterTable::isChanged(Row row) const
{
    const RowWidgets &w = m_rows.at(row);
    return m_pendingKnown && (!w.holdsValue || *w.holdsValue != w.edit->value());
}

bool ParameterTable::anyChanged() const
{
    for (int r = 0; r < kRowCount; ++r) {
        if (isChanged(Row(r)))
            return true;
    }
    return false;
}

void ParameterTable::refreshHighlight()
{
    for (int r = 0; r < kRowCount; ++r) {
        RowWidgets &w = m_rows[r];
        const bool changed = isChanged(Row(r));
        if (w.edit->property(kChangedProperty).toBool() == changed)
            continue;
        w.edit->setProperty(kChangedProperty, changed);
        w.edit->style()->unpolish(w.edit);
        w.edit->style()->polish(w.edit);
        QFont f = w.name->font();
        f.setBold(changed);
        w.name->setFont(f);
    }
}

void ParameterTable::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyChangedStyle();
}

void ParameterTable::applyChangedStyle()
{
    const QString sheet =
        QStringLiteral("QSpinBox[changed=\"true\"] { background: %1; }")
            .arg(StatusColors::background(StatusColors::Role::Warning, palette()).name());
    if (sheet != styleSheet()) // a style sheet change must not loop through PaletteChange
        setStyleSheet(sheet);
}

bool ParameterTable::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::FocusIn) {
        for (int r = 0; r < kRowCount; ++r) {
            if (m_rows[r].edit == watched)
                emit loopFocused(loopOf(Row(r)));
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace lk::ui
