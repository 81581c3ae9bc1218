#include "ControlWatch.h"

#include "ArgParser.h"
#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "Subcommand.h"

#include <bus/SpeedWatch.h>
#include <protocol/Command.h>
#include <system/SignalWatcher.h>

#include <QtCore/QElapsedTimer>

#include <cmath>

namespace lk::lkctl {

using protocol::Command;

namespace {
QString dps(double v)
{
    return QString::number(v, 'f', 0);
}

QString modeName(const protocol::Request &r)
{
    return r.command == Command::OpenLoop ? QStringLiteral("open loop") : QStringLiteral("torque");
}

using End = ControlWatch::End;

QString endText(End e)
{
    return e == End::Signal     ? QStringLiteral("Interrupted")
           : e == End::LinkLost ? QStringLiteral("The link went away")
                                : QStringLiteral("Watch over");
}

QString endName(End e)
{
    switch (e) {
    case End::Time:
        return QStringLiteral("time");
    case End::Signal:
        return QStringLiteral("signal");
    case End::SpeedLimit:
        return QStringLiteral("speed_limit");
    case End::LinkLost:
        return QStringLiteral("link_lost");
    }
    return {};
}

/// The fastest speed read of a drive, or that none was read (never shown as 0 dps).
QString peakText(const QMap<int, double> &peak, int id)
{
    return peak.contains(id) ? dps(peak.value(id)) + QStringLiteral(" dps")
                             : QStringLiteral("no speed read");
}

QByteArray peakJson(const QMap<int, double> &peak, int id)
{
    return peak.contains(id) ? protocol::OrderedJson::realText(peak.value(id)) : "null";
}
} // namespace

void ControlWatch::declare(ArgParser &parser)
{
    parser.addOption(QStringLiteral("watch"), true);
}

QString ControlWatch::helpText()
{
    return QStringLiteral(
        "  --watch SECONDS        torque and open-loop only (no drive bounds their speed):\n"
        "                         stay for SECONDS (0.1..86400), reading the drive's speed\n"
        "                         back to back (every 2-3 ms at 115200 baud), and send it\n"
        "                         Motor Stop (motor_stop, 0x81) as soon as it turns faster\n"
        "                         than the speed limit + 5 % (at least +30 dps; exit 6), at\n"
        "                         the end of SECONDS and on Ctrl+C or SIGTERM. With --json a\n"
        "                         second line: {\"watch\":{\"id\":3,\"watched_s\":2.5,\n"
        "                         \"ended\":\"signal\",\"limit_dps\":720,...}}. Without it\n"
        "                         the drive keeps the command, unwatched, once lkctl exits\n"
        "                         (the output says so)\n");
}

QString ControlWatch::exitStatusLine()
{
    return QStringLiteral(
        "  6  --watch: the drive turned faster than the speed limit and was stopped\n"
        "     (Motor Stop acknowledged; exit 1 when it was not)\n");
}

std::optional<ControlWatch> ControlWatch::read(const ArgParser &parser, QString *error)
{
    ControlWatch w;
    if (!parser.isSet(QStringLiteral("watch")))
        return w;
    const QString mode = parser.positionals().value(1);
    const bool group = parser.positionals().value(0) == QStringLiteral("multi-torque");
    if (!group && mode != QStringLiteral("torque") && mode != QStringLiteral("open-loop")) {
        *error = QStringLiteral("--watch goes with torque, open-loop and multi-torque only (the "
                                "drive bounds the speed of the other modes itself)");
        return std::nullopt;
    }
    const std::optional<double> seconds = parser.numberValue(QStringLiteral("watch"), 0.1, error);
    if (!seconds)
        return std::nullopt;
    if (*seconds > kMaxSeconds) {
        *error = QStringLiteral("--watch takes 0.1..%1 seconds").arg(kMaxSeconds);
        return std::nullopt;
    }
    w.m_seconds = *seconds;
    return w;
}

void ControlWatch::arm(LiveBus &bus, int id, const safety::SoftLimits &limits)
{
    m_limits.insert(id, limits);
    bus.session().setSoftLimits(id, limits);
}

int ControlWatch::follow(LiveBus &bus, const protocol::Request &request, bool json,
                         int status) const
{
    if (!bus::SpeedWatch::drives(request))
        return status;
    if (m_seconds > 0 && (status == kExitOk || status == kExitFailure)) // it may have acted
        return watch(bus, {request.id}, json, status);
    if (status != kExitOk)
        return status;
    const QString note =
        QStringLiteral("drive %1 stays under %2 after lkctl exits, and nothing watches its speed "
                       "(a drive does not bound torque or open loop): stop it with 'lkctl stop "
                       "%1', or give --watch SECONDS")
            .arg(request.id)
            .arg(modeName(request));
    if (json)
        bus.error(QStringLiteral("note: ") + note); // stdout stays one JSON line
    else
        bus.console().outLine(QStringLiteral("Note: ") + note + QLatin1Char('.'));
    return status;
}

int ControlWatch::followGroup(LiveBus &bus, const QVector<protocol::Request> &torques, bool json,
                              int status) const
{
    QVector<int> ids;
    for (const protocol::Request &r : torques) {
        if (bus::SpeedWatch::drives(r))
            ids.append(r.id);
    }
    if (ids.isEmpty())
        return status;
    if (m_seconds > 0 && (status == kExitOk || status == kExitFailure)) // they may have acted
        return watch(bus, ids, json, status);
    if (status != kExitOk)
        return status;
    const QString note =
        QStringLiteral("drives %1 stay under torque after lkctl exits, and nothing watches their "
                       "speed (a drive does not bound torque): stop them with 'lkctl off', or "
                       "give --watch SECONDS")
            .arg(idList(ids));
    if (json)
        bus.error(QStringLiteral("note: ") + note);
    else
        bus.console().outLine(QStringLiteral("Note: ") + note + QLatin1Char('.'));
    return status;
}

int ControlWatch::watch(LiveBus &bus, const QVector<int> &ids, bool json, int status) const
{
    const bool single = ids.size() == 1;
    const int id = ids.first();
    const double limit = limitOf(id);
    const double threshold = bus::SpeedWatch::thresholdDps(limit);
    // Before the first line: whoever reads "Watching" may press Ctrl+C at once.
    int signalled = 0;
    system::SignalWatcher terminations;
    const auto c4 = QObject::connect(&terminations, &system::SignalWatcher::signalled,
                                     [&signalled](int n) { signalled = n; });
    if (!json)
        bus.console().outLine(
            single ? QStringLiteral("Watching drive %1 for %2 s: Motor Stop above %3 dps (speed "
                                    "limit %4 dps + margin); Ctrl+C stops it now.")
                         .arg(id)
                         .arg(m_seconds)
                         .arg(dps(threshold), dps(limit))
                   : QStringLiteral("Watching drives %1 for %2 s: Motor Stop to all of them as "
                                    "soon as one turns faster than %3; Ctrl+C stops them now.")
                         .arg(idList(ids))
                         .arg(m_seconds)
                         .arg(thresholdList(ids)));
    bus.console().flush(); // a script or a person reads it while the drive turns
    std::optional<bus::SpeedWatchTrip> trip;
    QMap<int, double> peak;
    bool open = true;
    bus::BusSession &session = bus.session();
    const auto c1 = QObject::connect(&session, &bus::BusSession::speedWatchTripped,
                                     [&trip, &ids](const bus::SpeedWatchTrip &t) {
                                         if (ids.contains(t.id) && !trip)
                                             trip = t;
                                     });
    const auto c2 =
        QObject::connect(&session, &bus::BusSession::telemetryReceived,
                         [&peak, &ids](const bus::TelemetryBatch &batch) {
                             for (const bus::TelemetrySample &s : batch) {
                                 if (ids.contains(s.id) && s.has(bus::TelemetryField::Speed))
                                     peak[s.id] = std::max(peak.value(s.id), std::abs(s.speedDps));
                             }
                         });
    const auto c3 =
        QObject::connect(&session, &bus::BusSession::connectionChanged,
                         [&open](const bus::ConnectionStatus &s) { open = s.isOpen(); });
    QElapsedTimer clock;
    clock.start();
    const qint64 totalMs = qint64(std::llround(m_seconds * 1e3));
    const auto over = [&] { return trip || signalled || !open || clock.elapsed() >= totalMs; };
    while (!over())
        bus.waitUntil(over, int(std::min<qint64>(LiveBus::kMaxWaitMs, totalMs)));
    for (const auto &c : {c1, c2, c3, c4})
        QObject::disconnect(c);
    const End end =
        trip ? End::SpeedLimit : (!open ? End::LinkLost : (signalled ? End::Signal : End::Time));
    if (trip)
        peak[trip->id] = std::max(peak.value(trip->id), std::abs(trip->speedDps));
    // The watch's own stop has ended already; every other end stops the drives now (the
    // drives of a multi-motor frame beside the one that tripped get lkctl's own stop too).
    QMap<int, bool> acked;
    for (int d : ids)
        acked[d] = trip && trip->id == d ? trip->stopAcknowledged() : (open && stop(bus, d));
    const bool stopped = !acked.values().contains(false);
    const double seconds = clock.elapsed() / 1e3;
    const Outcome outcome{end, trip, peak, acked, seconds};
    if (single)
        reportOne(bus, id, json, outcome);
    else
        reportGroup(bus, ids, json, outcome);
    if (!stopped)
        return kExitFailure;
    return trip ? kExitWatchStopped : status;
}

QString ControlWatch::idList(const QVector<int> &ids)
{
    QStringList out;
    for (int id : ids)
        out << QString::number(id);
    return out.join(QStringLiteral(", "));
}

QString ControlWatch::thresholdList(const QVector<int> &ids) const
{
    QStringList out;
    for (int id : ids)
        out << QStringLiteral("%1 dps (drive %2, speed limit %3 dps + margin)")
                   .arg(dps(bus::SpeedWatch::thresholdDps(limitOf(id))))
                   .arg(id)
                   .arg(dps(limitOf(id)));
    return out.join(QStringLiteral(", "));
}

void ControlWatch::reportOne(LiveBus &bus, int id, bool json, const Outcome &o) const
{
    const double limit = limitOf(id);
    const double threshold = bus::SpeedWatch::thresholdDps(limit);
    const bool stopped = o.acked.value(id);
    if (json) {
        OrderedJson j;
        j.integer(QStringLiteral("id"), id)
            .real(QStringLiteral("watched_s"), std::round(o.seconds * 10) / 10)
            .text(QStringLiteral("ended"), endName(o.end))
            .real(QStringLiteral("limit_dps"), limit)
            .real(QStringLiteral("threshold_dps"), threshold)
            .raw(QStringLiteral("peak_dps"), peakJson(o.peak, id))
            .boolean(QStringLiteral("stop_acknowledged"), stopped);
        OrderedJson line;
        line.raw(QStringLiteral("watch"), j.toJson());
        bus.console().out(line.toJson() + '\n');
    } else if (o.trip) {
        bus.console().outLine(
            QStringLiteral("Drive %1 reached %2 dps, past %3 dps (speed limit %4 dps): the speed "
                           "watch sent Motor Stop (0x81) after %5 s, %6.")
                .arg(id)
                .arg(dps(o.trip->speedDps), dps(threshold), dps(limit))
                .arg(o.seconds, 0, 'f', 1)
                .arg(stopped ? QStringLiteral("acknowledged")
                             : QStringLiteral("NOT acknowledged: it may still be turning")));
    } else {
        bus.console().outLine(
            QStringLiteral("%1 after %2 s (peak %3): %4")
                .arg(endText(o.end))
                .arg(o.seconds, 0, 'f', 1)
                .arg(peakText(o.peak, id))
                .arg(o.end == End::LinkLost
                         ? QStringLiteral("nothing could be sent; drive %1 may still be turning")
                               .arg(id)
                     : stopped ? QStringLiteral("drive %1 acknowledged Motor Stop (0x81).").arg(id)
                               : QStringLiteral("drive %1 did NOT acknowledge Motor Stop "
                                                "(0x81): it may still be turning.")
                                     .arg(id)));
    }
}

void ControlWatch::reportGroup(LiveBus &bus, const QVector<int> &ids, bool json,
                               const Outcome &o) const
{
    if (json) {
        QByteArray drives = "[";
        for (int id : ids) {
            OrderedJson d;
            d.integer(QStringLiteral("id"), id)
                .real(QStringLiteral("limit_dps"), limitOf(id))
                .real(QStringLiteral("threshold_dps"), bus::SpeedWatch::thresholdDps(limitOf(id)))
                .raw(QStringLiteral("peak_dps"), peakJson(o.peak, id))
                .boolean(QStringLiteral("stop_acknowledged"), o.acked.value(id));
            drives += (drives.size() > 1 ? "," : "") + d.toJson();
        }
        drives += ']';
        OrderedJson j;
        j.raw(QStringLiteral("ids"), '[' + idList(ids).remove(QLatin1Char(' ')).toLatin1() + ']')
            .real(QStringLiteral("watched_s"), std::round(o.seconds * 10) / 10)
            .text(QStringLiteral("ended"), endName(o.end));
        if (o.trip)
            j.integer(QStringLiteral("tripped_id"), o.trip->id);
        j.raw(QStringLiteral("drives"), drives);
        OrderedJson line;
        line.raw(QStringLiteral("watch"), j.toJson());
        bus.console().out(line.toJson() + '\n');
        return;
    }
    if (o.trip)
        bus.console().outLine(
            QStringLiteral("Drive %1 reached %2 dps, past %3 dps (speed limit %4 dps): the speed "
                           "watch sent Motor Stop (0x81) to drives %5 after %6 s.")
                .arg(o.trip->id)
                .arg(dps(o.trip->speedDps), dps(bus::SpeedWatch::thresholdDps(limitOf(o.trip->id))),
                     dps(limitOf(o.trip->id)), idList(ids))
                .arg(o.seconds, 0, 'f', 1));
    else
        bus.console().outLine(
            QStringLiteral("%1 after %2 s.").arg(endText(o.end)).arg(o.seconds, 0, 'f', 1));
    for (int id : ids)
        bus.console().outLine(
            QStringLiteral("  drive %1: peak %2, %3")
                .arg(id)
                .arg(peakText(o.peak, id))
                .arg(o.end == End::LinkLost && !(o.trip && o.trip->id == id)
                         ? QStringLiteral("nothing could be sent: it may still be turning")
                     : o.acked.value(id)
                         ? QStringLiteral("acknowledged Motor Stop (0x81)")
                         : QStringLiteral("did NOT acknowledge Motor Stop (0x81): it may still be "
                                          "turning")));
}

bool ControlWatch::stop(LiveBus &bus, int id)
{
    return bus.request(Command::MotorStop, id, bus::Priority::Emergency).ok();
}

} // namespace lk::lkctl
