#include "EmergencyStopReport.h"

#include <panels/StatusColors.h>

namespace lk::ui {

namespace {
QString idList(const QVector<int> &ids)
{
    QStringList parts;
    for (int id : ids)
        parts << QString::number(id);
    return parts.join(QStringLiteral(", "));
}

QString redBold(const QString &html)
{
    return QStringLiteral("<b><span style=\"color:%1\">%2</span></b>")
        .arg(StatusColors::text(StatusColors::Role::Error).name(), html);
}
} // namespace

EmergencyStopReport::Text EmergencyStopReport::compose(const Context &p, const Outcome &outcome)
{
    using Level = MessageBanner::Level;
    const QVector<int> &acknowledged = outcome.acknowledged;
    const int total = int(acknowledged.size() + outcome.silent.size());
    const int sent = total - int(outcome.unsent.size());
    if (sent == 0) {
        const QString what =
            p.commanded.isEmpty()
                ? tr("Emergency stop: NOTHING could be sent, the bus is not connected. lkstudio "
                     "has not commanded any drive to move.")
                : tr("Emergency stop: NOTHING could be sent, the bus is not connected. Last "
                     "commanded to move: %1. They may still be moving: cut their power if "
                     "needed.")
                      .arg(p.commanded.join(QStringLiteral("; ")).toHtmlEscaped());
        return {Level::Error, redBold(what)};
    }
    // A watched drive that stayed silent either never got the halt (the link dropped before
    // it went out) or got it and did not answer: both may still be moving, said apart.
    QVector<int> noAnswer, neverSent;
    for (int id : outcome.silent) {
        if (p.watched.contains(id))
            (outcome.unsent.contains(id) ? neverSent : noAnswer).append(id);
    }
    QString text =
        acknowledged.isEmpty()
            ? tr("Emergency stop: Motor Off sent to %n ID(s); no drive answered.", nullptr, sent)
            : tr("Emergency stop: Motor Off sent to %n ID(s); acknowledged by "
                 "drive(s) %1.",
                 nullptr, sent)
                  .arg(idList(acknowledged));
    if (sent < total)
        text += QLatin1Char(' ') +
                tr("%1 of %2 could not be sent: the link dropped.").arg(total - sent).arg(total);
    text = text.toHtmlEscaped();
    if (!neverSent.isEmpty())
        text += QLatin1Char(' ') +
                redBold(tr("Motor Off NEVER reached drive(s) %1: they may still be moving, cut "
                           "their power if needed.")
                            .arg(idList(neverSent)));
    if (!noAnswer.isEmpty())
        text += QLatin1Char(' ') +
                redBold(tr("NO answer from drive(s) %1: check them and cut their power if needed.")
                            .arg(idList(noAnswer)));
    const Level level = !noAnswer.isEmpty() || !neverSent.isEmpty() || sent < total ? Level::Error
                        : acknowledged.isEmpty()                                    ? Level::Warning
                                                                                    : Level::Info;
    return {level, text};
}

} // namespace lk::ui
