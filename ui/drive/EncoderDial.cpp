#include "EncoderDial.h"

#include <panels/StatusColors.h>

#include <QtGui/QPainter>
#include <QtGui/QPainterPath>

#include <cmath>

namespace lk::ui {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kMajorTicks = 12; // every 30 degrees

// A point on the dial: 0 deg at the top, clockwise.
QPointF onDial(double deg, double radius)
{
    const double a = (deg - 90.0) * kPi / 180.0;
    return {radius * std::cos(a), radius * std::sin(a)};
}
} // namespace

EncoderDial::EncoderDial(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("encoderDial"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void EncoderDial::setReading(std::optional<int> encoder, std::optional<int> raw,
                             std::optional<int> offset, int countsPerTurn)
{
    m_encoder = encoder;
    m_raw = raw;
    m_offset = offset;
    m_counts = countsPerTurn > 0 ? countsPerTurn : 1;
    update();
}

void EncoderDial::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double side = std::min(width(), height()) - 8.0;
    const double r = side / 2;
    p.translate(width() / 2.0, height() / 2.0);

    const QPalette pal = palette();
    p.setPen(QPen(pal.color(QPalette::Mid), 1.5));
    p.setBrush(pal.color(QPalette::Base));
    p.drawEllipse(QPointF(0, 0), r, r);
    for (int i = 0; i < kMajorTicks; ++i) {
        const double deg = i * 360.0 / kMajorTicks;
        p.drawLine(onDial(deg, r * 0.88), onDial(deg, r));
    }
    p.setPen(pal.color(QPalette::Text));
    const QFontMetricsF fm(font());
    for (int deg : {0, 90, 180, 270}) {
        const QString text = QString::number(deg);
        const QPointF at = onDial(deg, r * 0.74);
        p.drawText(QRectF(at.x() - 20, at.y() - fm.height() / 2, 40, fm.height()), Qt::AlignCenter,
                   text);
    }
    auto degOf = [this](int counts) { return 360.0 * counts / m_counts; };
    // Drawn in raw terms: the needle is the raw position, the red mark the offset (where the
    // encoder reads 0); the encoder value is the angle from the mark to the needle.
    if (m_offset) {
        p.setPen(QPen(StatusColors::text(StatusColors::Role::Error, pal), 4));
        p.drawLine(onDial(degOf(*m_offset), r * 0.84), onDial(degOf(*m_offset), r * 1.0));
    }
    if (m_raw) {
        p.setPen(QPen(StatusColors::text(StatusColors::Role::Busy, pal), 3, Qt::SolidLine,
                      Qt::RoundCap));
        p.drawLine(QPointF(0, 0), onDial(degOf(*m_raw), r * 0.85));
    }
    p.setBrush(pal.color(QPalette::Text));
    p.setPen(Qt::NoPen);
    p.drawEllipse(QPointF(0, 0), 3, 3);
    p.setPen(pal.color(QPalette::Text));
    const QString centre = m_encoder ? QStringLiteral("%1\u00b0").arg(degOf(*m_encoder), 0, 'f', 1)
                                     : QStringLiteral("\u2013");
    p.drawText(QRectF(-r, r * 0.25, 2 * r, fm.height() * 1.5), Qt::AlignCenter, centre);
}

} // namespace lk::ui
