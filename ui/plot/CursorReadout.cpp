#include "CursorReadout.h"

#include "TelemetryStore.h"

#include <limits>

namespace lk::ui {

CursorReadout::CursorReadout(QWidget *parent) : QLabel(parent)
{
    setTextFormat(Qt::PlainText);
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setMinimumWidth(1); // long readouts must not widen the panel
}

void CursorReadout::showValues(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                               std::optional<double> cursorTime)
{
    const QString text = format(store, traces, cursorTime);
    if (text != this->text()) {
        setText(text);
    }
}

QString CursorReadout::format(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                              std::optional<double> cursorTime)
{
    const double at = cursorTime.value_or(std::numeric_limits<double>::infinity());
    QString text = cursorTime ? tr("t = %1 s").arg(*cursorTime, 0, 'f', 3) : tr("Latest");
    int drive = -1;
    QStringList values;
    auto flush = [&] {
        if (drive >= 0) {
            text += QStringLiteral("   ") + tr("ID %1: %2").arg(drive).arg(values.join(", "));
        }
        values.clear();
    };
    for (const PlotTrace &trace : traces) {
        if (trace.driveId != drive) {
            flush();
            drive = trace.driveId;
        }
        const std::optional<double> v = store.valueAt(trace.driveId, trace.channel, at);
        const QString number =
            v ? QString::number(*v, 'f', std::min(channelDecimals(trace.channel, trace.power), 3))
              : QStringLiteral("–");
        const QString unit = quantityUnit(trace.quantity());
        values << QStringLiteral("%1 %2%3").arg(channelLabel(trace.channel, trace.power), number,
                                                unit.isEmpty() || !v ? QString()
                                                                     : QStringLiteral(" ") + unit);
    }
    flush();
    return text;
}

} // namespace lk::ui
