#include "MessageBanner.h"

#include "BannerEntry.h"

#include <QtCore/QEvent>
#include <QtCore/QTimer>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr int kInfoHideMs = 8000;

BannerEntry::Level entryLevelOf(MessageBanner::Level level)
{
    switch (level) {
    case MessageBanner::Level::Info:
        return BannerEntry::Level::Info;
    case MessageBanner::Level::Warning:
        return BannerEntry::Level::Warning;
    case MessageBanner::Level::Error:
        break;
    }
    return BannerEntry::Level::Error;
}
} // namespace

MessageBanner::MessageBanner(QWidget *parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("messageBanner"));
    // The tinted boxes are children: a widget with its own style sheet is not told of palette
    // changes, and the banner must hear of them to re-tint for a dark or light desktop.
    m_layout = new QVBoxLayout(this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(2);
    m_box = new BannerEntry(this);
    m_layout->addWidget(m_box);
    m_autoHide = new QTimer(this);
    m_autoHide->setSingleShot(true);
    m_autoHide->setInterval(kInfoHideMs);
    connect(m_autoHide, &QTimer::timeout, this, &MessageBanner::clearMessage);
    connect(m_box, &BannerEntry::closeClicked, this, &MessageBanner::clearMessage);
    m_box->hide();
    hide();
}

void MessageBanner::showMessage(Level level, const QString &text)
{
    if (m_box->isVisibleTo(this) && text == m_lastText && level == m_level) {
        ++m_repeats;
    } else {
        m_repeats = 1;
        m_lastText = text;
        m_level = level;
        m_box->setLevel(entryLevelOf(level));
    }
    updateText();
    m_box->show();
    updateVisibility();
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
    m_box->hide();
    updateVisibility();
}

void MessageBanner::updateText()
{
    m_box->setText(m_repeats > 1 ? tr("%1 (\u00d7%2)").arg(m_lastText).arg(m_repeats) : m_lastText);
}

void MessageBanner::updateVisibility()
{
    setVisible(m_box->isVisibleTo(this) || !m_entries.isEmpty());
}

void MessageBanner::setEntry(const QString &key, Level level, const QString &html)
{
    BannerEntry *&entry = m_entries[key];
    if (!entry) {
        entry = new BannerEntry(this);
        entry->setObjectName(QStringLiteral("messageBox"));
        entry->setProperty("entryKey", key);
        m_layout->addWidget(entry);
        connect(entry, &BannerEntry::closeClicked, this, [this, key] {
            clearEntry(key);
            emit entryDismissed(key);
        });
        connect(entry, &BannerEntry::linkActivated, this,
                [this, key](const QString &link) { emit entryLinkActivated(key, link); });
    }
    entry->setLevel(entryLevelOf(level));
    entry->setText(html, Qt::RichText);
    updateVisibility();
}

void MessageBanner::clearEntry(const QString &key)
{
    BannerEntry *entry = m_entries.take(key);
    if (!entry)
        return;
    entry->hide();
    entry->deleteLater(); // it may be the sender of the click being handled
    updateVisibility();
}

QString MessageBanner::entryText(const QString &key) const
{
    const BannerEntry *entry = m_entries.value(key);
    return entry ? entry->text() : QString();
}

MessageBanner::Level MessageBanner::entryLevel(const QString &key) const
{
    const BannerEntry *entry = m_entries.value(key);
    if (!entry)
        return Level::Info;
    switch (entry->level()) {
    case BannerEntry::Level::Info:
        return Level::Info;
    case BannerEntry::Level::Warning:
        return Level::Warning;
    case BannerEntry::Level::Error:
        break;
    }
    return Level::Error;
}

QWidget *MessageBanner::entryCloseButton(const QString &key) const
{
    const BannerEntry *entry = m_entries.value(key);
    return entry ? entry->findChild<QToolButton *>(QStringLiteral("messageClose")) : nullptr;
}

void MessageBanner::changeEvent(QEvent *event)
{
    QFrame::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) {
        // Light/dark tints follow (the sheets are on the children: no loop).
        m_box->retint();
        for (BannerEntry *entry : std::as_const(m_entries))
            entry->retint();
    }
}

QString MessageBanner::tintStyle() const
{
    return m_box->tintStyle();
}

} // namespace lk::ui
