#include "Readout.h"

#include "StatusColors.h"

#include <QtCore/QEvent>
#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr double kValueScale = 1.7; // values are read from a distance on a bench
} // namespace

Readout::Readout(const QString &caption, QWidget *parent)
    : QWidget(parent), m_caption(new QLabel(caption, this)), m_value(new QLabel(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(0);
    QFont f = m_value->font();
    f.setPointSizeF(f.pointSizeF() * kValueScale);
    f.setBold(true);
    m_value->setFont(f);
    m_value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_caption->setWordWrap(true);
    layout->addWidget(m_caption);
    layout->addWidget(m_value);
    setValue({}, true);
}

void Readout::setCaption(const QString &caption)
{
    m_caption->setText(caption);
}

void Readout::setValue(const QString &value, bool stale)
{
    const QString shown = value.isEmpty() ? QStringLiteral("\u2013") : value;
    if (shown == m_value->text() && stale == m_stale)
        return;
    m_value->setText(shown);
    m_stale = stale || value.isEmpty();
    applyStyle();
}

void Readout::setAlarm(bool alarm)
{
    if (alarm == m_alarm)
        return;
    m_alarm = alarm;
    applyStyle();
}

QString Readout::value() const
{
    return m_value->text();
}

void Readout::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyStyle(); // the value label holds a palette of its own: follow a theme switch
}

void Readout::applyStyle()
{
    QPalette p = palette();
    QColor c = p.color(QPalette::WindowText);
    if (m_stale)
        c = p.color(QPalette::Disabled, QPalette::WindowText);
    else if (m_alarm)
        c = StatusColors::text(StatusColors::Role::Error, p);
    p.setColor(QPalette::WindowText, c);
    m_value->setPalette(p);
    m_value->setToolTip(m_stale ? tr("No update for over a second") : QString());
}

} // namespace lk::ui
