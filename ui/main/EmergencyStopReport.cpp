#include "EmergencyStopReport.h"

#include <panels/StatusColors.h>

#include <algorithm>

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

QVector<int> EmergencyStopReport::mayBeMoving(const Context &p, const Outcome &outcome)
{
    const int total = int(outcome.acknowledged.size() + outcome.silent.size());
    const bool nothingSent = outcome.remaining == 0 && total == int(outcome.unsent.size());
    QVector<int> ids;
    for (int id : p.watched) {
        const bool open = nothingSent || outcome.silent.contains(id);
        if (open && !outcome.sinceStopped.contains(id))
            ids.append(id);
    }
    return ids;
}

namespace {
/// The watched drives not yet heard from while a stop is under way.
QVector<int> waitingFor(const EmergencyStopReport::Context &p,
                        const EmergencyStopReport::Outcome &outcome)
{
    QVector<int> ids;
    for (int id : p.watched) {
        if (!outcome.acknowledged.contains(id) && !outcome.silent.contains(id))
            ids.append(id);
    }
    return ids;
}

QVector<int> sorted(QVector<int> ids)
{
    std::sort(ids.begin(), ids.end());
    return ids;
}
} // namespace

EmergencyStopReport::Text EmergencyStopReport::compose(const Context &p, const Outcome &outcome)
{
    using Level = MessageBanner::Level;
    QString resent;
    if (!p.pressedWhileDisconnectedAt.isEmpty())
        resent = tr("Pressed at %1 while the bus was not connected; sent as soon as it was back.")
                     .arg(p.pressedWhileDisconnectedAt) +
                 QLatin1Char(' ');
    const QVector<int> acknowledged = sorted(outcome.acknowledged);
    if (outcome.remaining > 0) {
        // Shown at once and filled in as the acknowledgements come, so that the operator
        // sees the stop happening rather than a banner that appears when it is all over.
        const int done = int(acknowledged.size() + outcome.silent.size());
        QString text = tr("Emergency stop: Motor Off going out to every ID 1-32 (%1 of %2 done).")
                           .arg(done)
                           .arg(done + outcome.remaining);
        if (!acknowledged.isEmpty())
            text += QLatin1Char(' ') +
                    tr("Acknowledged so far by drive(s) %1.").arg(idList(acknowledged));
        const QVector<int> waiting = waitingFor(p, outcome);
        if (!waiting.isEmpty())
            text += QLatin1Char(' ') + tr("Waiting for drive(s) %1.").arg(idList(waiting));
        return {Level::Warning, QStringLiteral("<b>%1</b>").arg((resent + text).toHtmlEscaped())};
    }
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
        const QString later = tr("Motor Off goes out to every drive as soon as this port is "
                                 "connected again (dismiss this message to cancel that).");
        return {Level::Error, redBold(what) + QLatin1Char(' ') + later.toHtmlEscaped()};
    }
    // A watched drive that stayed silent either never got the halt (the link dropped before
    // it went out) or got it and did not answer: both may still be moving, said apart, until
    // a state read shows them stopped.
    QVector<int> noAnswer, neverSent, stopped;
    for (int id : sorted(outcome.silent)) {
        if (!p.watched.contains(id))
            continue;
        if (outcome.sinceStopped.contains(id))
            stopped.append(id);
        else
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
    if (!stopped.isEmpty())
        text += QLatin1Char(' ') +
                tr("Drive(s) %1 did not answer but have since read stopped.").arg(idList(stopped));
    text = (resent + text).toHtmlEscaped();
    if (!neverSent.isEmpty())
        text += QLatin1Char(' ') +
                redBold(tr("Motor Off NEVER reached drive(s) %1: they may still be moving, cut "
                           "their power if needed.")
                            .arg(idList(neverSent)));
    if (!noAnswer.isEmpty())
        text += QLatin1Char(' ') +
                redBold(tr("NO answer from drive(s) %1: check them and cut their power if needed.")
                            .arg(idList(noAnswer)));
    const bool red = !noAnswer.isEmpty() || !neverSent.isEmpty();
    const Level level = red || (sent < total && stopped.isEmpty())    ? Level::Error
                        : acknowledged.isEmpty() && stopped.isEmpty() ? Level::Warning
                                                                      : Level::Info;
    return {level, text};
}

} // namespace lk::ui
