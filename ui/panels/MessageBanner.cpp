#include "MessageBanner.h"

#include "StatusColors.h"
#include "ThemedIcon.h"

#include <QtCore/QTimer>
#include <QtGui/QIcon>
#include <QtWidgets/QApplication>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QToolButton>

namespace lk::ui {

namespace {
constexpr int kInfoHideMs = 8000;
constexpr int kIconPx = 20;
} // namespace

MessageBanner::MessageBanner(QWidget *parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("messageBanner"));
    // The tinted box is a child: a widget with its own style sheet is not told of palette
    // changes, and the banner must hear of them to re-tint for a dark or light desktop.
    auto *outer = new QHBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    m_box = new QFrame(this);
    m_box->setObjectName(QStringLiteral("messageBox"));
    m_box->setFrameShape(QFrame::StyledPanel);
    outer->addWidget(m_box);
    auto *layout = new QHBoxLayout(m_box);
    layout->setContentsMargins(8, 4, 4, 4);
    m_icon = new QLabel(m_box);
    m_label = new QLabel(m_box);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_close = new QToolButton(m_box);
    m_close->setAutoRaise(true);
    m_close->setText(QStringLiteral("\u2715"));
    m_close->setToolTip(tr("Hide this message"));
    layout->addWidget(m_icon);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_close);
    m_autoHide = new QTimer(this);
    m_autoHide->setSingleShot(true);
    m_autoHide->setInterval(kInfoHideMs);
    connect(m_autoHide, &QTimer::timeout, this, &MessageBanner::clearMessage);
    connect(m_close, &QToolButton::clicked, this, &MessageBanner::clearMessage);
    hide();
}

void MessageBanner::showMessage(Level level, const QString &text)
{
    if (isVisible() && text == m_lastText && level == m_level) {
        ++m_repeats;
    } else {
        m_repeats = 1;
        m_lastText = text;
        m_level = level;
        applyLevel();
    }
    updateText();
    show();
    if (level == Level::Info)
        m_autoHide->start();
    else
        m_autoHide->stop();
}

void MessageBanner::clearMessage()
{
    m_autoHide->stop();
    m_lastText.clear();
    m_repeats = 0;
    hide();
}

void MessageBanner::applyLevel()
{
    QString icon;
    StatusColors::Role role = StatusColors::Role::Info;
    switch (m_level) {
    case Level::Info:
        icon = QStringLiteral(":/icons/info.svg");
        role = StatusColors::Role::Info;
        break;
    case Level::Warning:
        icon = QStringLiteral(":/icons/warning.svg");
        role = StatusColors::Role::Warning;
        break;
    case Level::Error:
        icon = QStringLiteral(":/icons/error.svg");
        role = StatusColors::Role::Error;
        break;
    }
    // Tints that suit the palette: pale on a light window, deep on a dark one.
    const QPalette pal = QApplication::palette(); // not ours: the style sheet tints it
    m_box->setStyleSheet(QStringLiteral("#messageBox { background: %1; border: 1px solid %2; }"
                                        " QLabel { color: %3; }")
                             .arg(StatusColors::background(role, pal).name(),
                                  StatusColors::border(role, pal).name(),
                                  StatusColors::text(role, pal).name()));
    m_icon->setPixmap(ThemedIcon::get(icon).pixmap(kIconPx, kIconPx));
}

void MessageBanner::updateText()
{
    m_label->setText(m_repeats > 1 ? tr("%1 (\u00d7%2)").arg(m_lastText).arg(m_repeats)
                                   : m_lastText);
}

void MessageBanner::changeEvent(QEvent *event)
{
    QFrame::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyLevel(); // light/dark tints follow (the sheet is on m_box: no loop)
}

QString MessageBanner::tintStyle() const
{
    return m_box->styleSheet();
}

} // namespace lk::ui
