#pragma once

#include <QtGui/QIcon>
#include <QtGui/QIconEngine>

namespace lk::ui {

/// An icon that picks its light or dark drawing each time it is painted, from the application
/// palette of that moment: a toolbar set up on a light desktop follows a switch to dark
/// without anyone setting its icons again.
class ThemedIconEngine : public QIconEngine {
public:
    ThemedIconEngine(const QIcon &light, const QIcon &dark);

    void paint(QPainter *painter, const QRect &rect, QIcon::Mode mode, QIcon::State state) override;
    QPixmap pixmap(const QSize &size, QIcon::Mode mode, QIcon::State state) override;
    QPixmap scaledPixmap(const QSize &size, QIcon::Mode mode, QIcon::State state,
                         qreal scale) override;
    QSize actualSize(const QSize &size, QIcon::Mode mode, QIcon::State state) override;
    QList<QSize> availableSizes(QIcon::Mode mode, QIcon::State state) override;
    QIconEngine *clone() const override;
    QString key() const override;

private:
    const QIcon &current() const;

    QIcon m_light;
    QIcon m_dark;
};

} // namespace lk::ui
