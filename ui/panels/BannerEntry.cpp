#include "BannerEntry.h"

#include "StatusColors.h"
#include "ThemedIcon.h"

#include <QtGui/QIcon>
#include <QtWidgets/QApplication>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QToolButton>

namespace lk::ui {

namespace {
constexpr int kIconPx = 20;
} // namespace

BannerEntry::BannerEntry(QWidget *parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("messageBox"));
    setFrameShape(QFrame::StyledPanel);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 4, 4);
    m_icon = new QLabel(this);
    m_label = new QLabel(this);
    m_label->setObjectName(QStringLiteral("messageText"));
    m_label->setWordWrap(true);
    // Entries may offer an action as a link (the speed watch's "set the drive's Max Speed").
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::LinksAccessibleByMouse |
                                     Qt::LinksAccessibleByKeyboard);
    connect(m_label, &QLabel::linkActivated, this, &BannerEntry::linkActivated);
    m_close = new QToolButton(this);
    m_close->setObjectName(QStringLiteral("messageClose"));
    m_close->setAutoRaise(true);
    m_close->setText(QStringLiteral("\u2715"));
    m_close->setToolTip(tr("Hide this message"));
    layout->addWidget(m_icon, 0, Qt::AlignTop);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_close, 0, Qt::AlignTop);
    connect(m_close, &QToolButton::clicked, this, &BannerEntry::closeClicked);
    retint();
}

void BannerEntry::setLevel(Level level)
{
    if (m_level == level && !styleSheet().isEmpty())
        return;
    m_level = level;
    retint();
}

void BannerEntry::setText(const QString &text, Qt::TextFormat format)
{
    m_label->setTextFormat(format);
    m_label->setText(text);
}

QString BannerEntry::text() const
{
    return m_label->text();
}

void BannerEntry::retint()
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
    setStyleSheet(QStringLiteral("#messageBox { background: %1; border: 1px solid %2; }"
                                 " QLabel { color: %3; }")
                      .arg(StatusColors::background(role, pal).name(),
                           StatusColors::border(role, pal).name(),
                           StatusColors::text(role, pal).name()));
    m_icon->setPixmap(ThemedIcon::get(icon).pixmap(kIconPx, kIconPx));
}

} // namespace lk::ui
