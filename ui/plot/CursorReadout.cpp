#include "CursorReadout.h"

#include "TelemetryStore.h"

#include <algorithm>
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
    showText(format(store, traces, cursorTime));
}

void CursorReadout::showText(const QString &text)
{
    if (text != this->text()) {
        setText(text);
    }
}

QString CursorReadout::line(std::optional<double> cursorTime, const QStringList &groups)
{
    QString text = cursorTime ? tr("t = %1 s").arg(*cursorTime, 0, 'f', 3) : tr("Latest");
    for (const QString &group : groups) {
        text += QStringLiteral("   ") + group;
    }
    return text;
}

QString CursorReadout::value(const QString &label, std::optional<double> v, int decimals,
                             const QString &unit)
{
    const QString number = v ? QString::number(*v, 'f', decimals) : QStringLiteral("–");
    return QStringLiteral("%1 %2%3").arg(
        label, number, unit.isEmpty() || !v ? QString() : QStringLiteral(" ") + unit);
}

QString CursorReadout::format(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                              std::optional<double> cursorTime)
{
    const double at = cursorTime.value_or(std::numeric_limits<double>::infinity());
    QStringList groups;
    int drive = -1;
    QStringList values;
    auto flush = [&] {
        if (drive >= 0) {
            groups << tr("ID %1: %2").arg(drive).arg(values.join(", "));
        }
        values.clear();
    };
    for (const PlotTrace &trace : traces) {
        if (trace.driveId != drive) {
            flush();
            drive = trace.driveId;
        }
        values << value(channelLabel(trace.channel, trace.power),
                        store.valueAt(trace.driveId, trace.channel, at),
                        std::min(channelDecimals(trace.channel, trace.power), 3),
                        quantityUnit(trace.quantity()));
    }
    flush();
    return line(cursorTime, groups);
}

} // namespace lk::ui
