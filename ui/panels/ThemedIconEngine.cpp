#include "ThemedIconEngine.h"

#include "StatusColors.h"

#include <QtGui/QPainter>

namespace lk::ui {

ThemedIconEngine::ThemedIconEngine(const QIcon &light, const QIcon &dark)
    : m_light(light), m_dark(dark)
{
}

const QIcon &ThemedIconEngine::current() const
{
    return StatusColors::isDark(StatusColors::current()) ? m_dark : m_light;
}

void ThemedIconEngine::paint(QPainter *painter, const QRect &rect, QIcon::Mode mode,
                             QIcon::State state)
{
    current().paint(painter, rect, Qt::AlignCenter, mode, state);
}

QPixmap ThemedIconEngine::pixmap(const QSize &size, QIcon::Mode mode, QIcon::State state)
{
    return current().pixmap(size, mode, state);
}

QPixmap ThemedIconEngine::scaledPixmap(const QSize &size, QIcon::Mode mode, QIcon::State state,
                                       qreal scale)
{
    // High-DPI: the SVG is rendered at the device pixel ratio, not scaled up from 1x.
    return current().pixmap(size, scale, mode, state);
}

QSize ThemedIconEngine::actualSize(const QSize &size, QIcon::Mode mode, QIcon::State state)
{
    return current().actualSize(size, mode, state);
}

QList<QSize> ThemedIconEngine::availableSizes(QIcon::Mode mode, QIcon::State state)
{
    return current().availableSizes(mode, state);
}

QIconEngine *ThemedIconEngine::clone() const
{
    return new ThemedIconEngine(m_light, m_dark);
}

QString ThemedIconEngine::key() const
{
    return QStringLiteral("lk-themed");
}

} // namespace lk::ui
