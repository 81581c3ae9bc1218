#pragma once

#include <QtWidgets/QFrame>

class QLabel;
class QToolButton;

namespace lk::ui {

/// One tinted line of the message banner: an icon for its level, the text, and a close
/// button. Its own style sheet keeps it from hearing of palette changes: the banner calls
/// retint() when the palette (light or dark) changes.
class BannerEntry : public QFrame {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };

    explicit BannerEntry(QWidget *parent = nullptr);

    void setLevel(Level level);
    Level level() const { return m_level; }
    /// `format`: Qt::PlainText for messages built from outside text, Qt::RichText for
    /// messages that colour parts (their pieces escaped by the caller).
    void setText(const QString &text, Qt::TextFormat format = Qt::PlainText);
    QString text() const;
    /// The style sheet of the tinted box (for tests of the light/dark tint).
    QString tintStyle() const { return styleSheet(); }
    void retint();

signals:
    void closeClicked();
    /// A link in the text was clicked (its href): the entry's owner acts on it.
    void linkActivated(const QString &link);

private:
    QLabel *m_icon = nullptr;
    QLabel *m_label = nullptr;
    QToolButton *m_close = nullptr;
    Level m_level = Level::Info;
};

} // namespace lk::ui
