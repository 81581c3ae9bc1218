#pragma once

#include <QtCharts/QChartView>

#include <optional>

class QRubberBand;
class QValueAxis;

namespace lk::ui {

/// A chart view whose mouse acts on the time axis only: drag pans, Shift+drag or right-drag
/// selects a range (rubber band), the wheel zooms around the mouse, Ctrl+wheel scales the
/// value axes; it draws the shared cursor line and reports the time under the mouse. It
/// changes no axis itself: the panel decides and redraws every chart alike.
class TimeChartView : public QChartView {
    Q_OBJECT
public:
    explicit TimeChartView(QWidget *parent = nullptr);

    /// Time of the vertical cursor line, or none.
    void setCursorTime(std::optional<double> time);
    std::optional<double> cursorTime() const { return m_cursorTime; }
    /// The horizontal (time) axis of the chart, if it has one.
    QValueAxis *timeAxis() const;
    /// Colour the chart (background, axes, grid, labels, legend) from the widget's palette,
    /// so that a dark system theme gets a dark chart. Called on every palette change; call
    /// it again after adding axes.
    virtual void applyPalette();

signals:
    void cursorMoved(double time);
    void cursorLeft();
    void panRequested(double seconds); ///< positive: show later times
    void zoomRequested(double factor, double anchorTime);
    void rangeSelected(double t0, double t1);
    void valueZoomRequested(double factor);

protected:
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void leaveEvent(QEvent *event) override;
    void changeEvent(QEvent *event) override;
    void drawForeground(QPainter *painter, const QRectF &rect) override;
    void drawBackground(QPainter *painter, const QRectF &rect) override;

private:
    enum class Drag { None, Pan, Select };
    double timeAtX(double viewX) const;
    std::optional<double> cursorX(double time) const; ///< chart x of a time, if on the plot
    QRect cursorStrip(std::optional<double> time) const;
    double secondsPerPixel() const;
    QRectF plotAreaInView() const;
    QRectF chartBackgroundInScene() const;

    Drag m_drag = Drag::None;
    double m_lastX = 0;
    double m_selectStartX = 0;
    QRubberBand *m_band = nullptr;
    std::optional<double> m_cursorTime;
};

} // namespace lk::ui
