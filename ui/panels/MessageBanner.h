#pragma once

#include <QtCore/QMap>
#include <QtWidgets/QFrame>

class QTimer;
class QVBoxLayout;

namespace lk::ui {

class BannerEntry;

/// The message strip above the views. One transient line: a new message replaces the old
/// one, the same message again only counts up (a flapping link never floods the screen),
/// Info hides by itself. Below it, keyed entries that stay until the user dismisses them (or
/// their owner clears them): the emergency stop's report, one "may still be moving" warning
/// per drive. Each line has its own close button.
class MessageBanner : public QFrame {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };
    Q_ENUM(Level)

    explicit MessageBanner(QWidget *parent = nullptr);

    /// Show `text` (plain) on the transient line; Info messages hide after a few seconds.
    void showMessage(Level level, const QString &text);
    void clearMessage();
    QString text() const { return m_lastText; }
    /// The style sheet of the transient line's tinted box (for tests of the light/dark tint).
    QString tintStyle() const;
    Level level() const { return m_level; }

    /// Show or replace the entry `key`: rich text (the caller escapes its pieces) that stays
    /// until dismissed (entryDismissed follows) or cleared.
    void setEntry(const QString &key, Level level, const QString &html);
    /// Remove the entry `key` without a signal; nothing when there is none.
    void clearEntry(const QString &key);
    bool hasEntry(const QString &key) const { return m_entries.contains(key); }
    QStringList entryKeys() const { return m_entries.keys(); }
    /// The entry's text as shown (rich text source); empty when there is none.
    QString entryText(const QString &key) const;
    Level entryLevel(const QString &key) const;
    /// The entry's close button (tests click it).
    QWidget *entryCloseButton(const QString &key) const;

signals:
    /// The user closed the entry `key` (acknowledged it).
    void entryDismissed(const QString &key);
    /// The user clicked a link (`<a href="link">`) in the entry `key`: its owner acts.
    void entryLinkActivated(const QString &key, const QString &link);

protected:
    void changeEvent(QEvent *event) override;

private:
    void updateText();
    void updateVisibility();

    QVBoxLayout *m_layout = nullptr;
    BannerEntry *m_box = nullptr; ///< the transient line
    QMap<QString, BannerEntry *> m_entries;
    QTimer *m_autoHide = nullptr;
    QString m_lastText;
    Level m_level = Level::Info;
    int m_repeats = 0;
};

} // namespace lk::ui
