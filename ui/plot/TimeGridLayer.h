#pragma once

#include <QtGui/QColor>
#include <QtGui/QFont>
#include <QtWidgets/QGraphicsItem>

class QChart;
class QValueAxis;

namespace lk::ui {

/// The time grid of a StripChart and, on the bottom strip, its time labels and title, drawn by
/// one graphics item from the (hidden) time axis's range. A visible QValueAxis lays out every
/// grid line and a rich-text label per tick again whenever its range moves, which a live plot's
/// time axis does at every frame: that was a third of the GUI thread with every signal plotted.
/// Drawing the few lines and labels takes a small part of that.
class TimeGridLayer : public QGraphicsItem {
public:
    /// Pixels a time label needs ("1234.5" and a gap): a narrower plot gets fewer ticks.
    static constexpr int kPixelsPerTick = 90;
    static constexpr int kMaxTicks = 8;

    /// A child of `chart`, at the grid's depth (under the traces), reading `timeAxis`'s range.
    TimeGridLayer(QChart *chart, QValueAxis *timeAxis);

    /// Labels and `title` under the plot area (the bottom strip), or only the grid.
    void setLabels(bool visible, const QString &title);
    bool labelsVisible() const { return m_labels; }
    /// The height the labels and the title take under the plot area (0 without labels): the
    /// chart keeps that much margin for them.
    int labelAreaHeight() const;
    void setColors(const QColor &grid, const QColor &line, const QColor &text);
    /// The fonts of the labels and of the title (the chart theme's axis fonts, which the
    /// hidden time axis carries, for the value axes' look).
    void setFonts(const QFont &labels, const QFont &title);
    /// The plot area moved or resized: the bounds follow, and it repaints. (A new time range
    /// only needs update().)
    void plotAreaChanged();

    /// The tick interval for `span` seconds over `columns` pixels: a round step (1, 2 or 5
    /// x 10^k) giving at most kMaxTicks ticks and about one per kPixelsPerTick.
    static double tickStep(double span, int columns);
    /// The tick times in [t0, t1]: the multiples of tickStep.
    static QVector<double> ticks(double t0, double t1, int columns);

    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

private:
    QChart *m_chart;
    QValueAxis *m_time;
    QRectF m_area;
    bool m_labels = false;
    QString m_title;
    QFont m_font;
    QFont m_titleFont;
    QColor m_grid, m_line, m_text;
};

} // namespace lk::ui
