#include "ElidedLabel.h"

#include <QtGui/QFontMetrics>

#include <algorithm>

namespace lk::ui {

namespace {
constexpr int kMinimumCharacters = 12; ///< "Connected: …" still tells the state
} // namespace

ElidedLabel::ElidedLabel(QWidget *parent) : QLabel(parent)
{
    setTextFormat(Qt::PlainText);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void ElidedLabel::setFullText(const QString &text)
{
    if (text == m_full)
        return;
    m_full = text;
    updateGeometry(); // the size it asks for follows the whole text
    elide();
}

void ElidedLabel::setDetail(const QString &detail)
{
    m_detail = detail;
    elide();
}

QSize ElidedLabel::sizeHint() const
{
    const QMargins m = contentsMargins();
    return {fontMetrics().horizontalAdvance(m_full) + m.left() + m.right() + 2 * margin(),
            QLabel::sizeHint().height()};
}

QSize ElidedLabel::minimumSizeHint() const
{
    const QMargins m = contentsMargins();
    const int least = fontMetrics().averageCharWidth() * kMinimumCharacters;
    return {std::min(least, sizeHint().width()) + m.left() + m.right(),
            QLabel::minimumSizeHint().height()};
}

void ElidedLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    elide();
}

void ElidedLabel::elide()
{
    const QString shown = fontMetrics().elidedText(m_full, Qt::ElideRight, contentsRect().width());
    if (shown != text())
        setText(shown); // QLabel::setText relayouts: only when the shown text changes
    const QString tip =
        shown == m_full
            ? m_detail
            : (m_detail.isEmpty() ? m_full : QStringLiteral("%1\n%2").arg(m_full, m_detail));
    if (tip != toolTip())
        setToolTip(tip);
}

} // namespace lk::ui
