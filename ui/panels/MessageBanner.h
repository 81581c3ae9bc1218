#pragma once

#include <QtWidgets/QFrame>

class QLabel;
class QToolButton;
class QTimer;

namespace lk::ui {

/// A one-line, non-modal message strip above the views. A new message replaces the old one;
/// the same message again only counts up, so a flapping link never floods the screen.
class MessageBanner : public QFrame {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };
    Q_ENUM(Level)

    explicit MessageBanner(QWidget *parent = nullptr);

    /// Show `text`; Info messages hide by themselves after a few seconds.
    void showMessage(Level level, const QString &text);
    void clearMessage();
    QString text() const { return m_lastText; }
    /// The style sheet of the tinted box (for tests of the light/dark tint).
    QString tintStyle() const;
    Level level() const { return m_level; }
    int repeatCount() const { return m_repeats; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void applyLevel();
    void updateText();

    QFrame *m_box = nullptr; ///< the tinted box (carries the style sheet)
    QLabel *m_icon = nullptr;
    QLabel *m_label = nullptr;
    QToolButton *m_close = nullptr;
    QTimer *m_autoHide = nullptr;
    QString m_lastText;
    Level m_level = Level::Info;
    int m_repeats = 0;
};

} // namespace lk::ui
