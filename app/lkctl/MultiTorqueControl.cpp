#include "MultiTorqueControl.h"

#include "ArgParser.h"
#include "Console.h"
#include "ControlWatch.h"
#include "LiveBus.h"
#include "MotionLimitOptions.h"
#include "OrderedJson.h"
#include "ReplyText.h"
#include "Subcommand.h"

#include <protocol/CanRecord.h>
#include <protocol/FieldJson.h>
#include <protocol/RequestBuilder.h>
#include <safety/MultiTorqueGuard.h>
#include <text/VerdictText.h>

#include <QtCore/QMap>
#include <QtCore/QSet>

#include <algorithm>
#include <cmath>

namespace lk::lkctl {

using protocol::FieldJson;

namespace {
int usage(Console &console, const QString &command, const QString &message)
{
    console.errLine(QStringLiteral("lkctl %1: %2").arg(command, message));
    return kExitUsage;
}

/// The drive `id` as --drives tells it (CAN has no model read).
std::optional<bus::DriveIdentity> identityOf(const BusOptions &options, int id)
{
    for (const bus::DriveIdentity &d : options.drives) {
        if (d.id == id)
            return d;
    }
    return std::nullopt;
}

/// The drives --drives declares: on CAN the only word lkctl has of who is on the bus.
QSet<int> declaredIds(const BusOptions &options)
{
    QSet<int> ids;
    for (const bus::DriveIdentity &d : options.drives)
        ids.insert(d.id);
    return ids;
}

QString frameText(const QVector<protocol::Request> &torques)
{
    const std::optional<protocol::CanRecord> r =
        protocol::CanRecord::decode(bus::encodeMultiTorque(torques));
    return r ? r->candumpText() : QString();
}
} // namespace

QString MultiTorqueControl::helpText()
{
    return QStringLiteral(
        "  multi-torque ID=IQ_A[,ID=IQ_A...]\n"
        "                         old CAN generation only: one multi-motor torque frame\n"
        "                         (0x280) for up to 4 drives, IDs 1..4, torque in A\n"
        "                         (+-32 A); each drive is checked as 'control ID torque'\n"
        "                         checks one (its series from --drives, its torque limit),\n"
        "                         and one refusal sends nothing to any drive. The frame\n"
        "                         carries 0 A to the IDs of 1..4 not named. The drives must\n"
        "                         be in their Broadcast Mode; each answers with its motion\n"
        "                         reply. --watch stops all of them (exit 1 when one stayed\n"
        "                         silent: it may not have heard)\n");
}

std::optional<QVector<MultiTorqueControl::Drive>>
MultiTorqueControl::parseDrives(const QString &text, QString *error)
{
    QVector<Drive> drives;
    QSet<int> seen;
    for (const QString &part : text.split(QLatin1Char(','))) {
        const QStringList kv = part.split(QLatin1Char('='));
        bool idOk = false;
        bool iqOk = false;
        const int id = kv.value(0).trimmed().toInt(&idOk);
        const double iq = kv.value(1).trimmed().toDouble(&iqOk);
        if (kv.size() != 2 || !idOk || !iqOk || !std::isfinite(iq)) {
            *error = QStringLiteral("multi-torque takes ID=IQ_A[,ID=IQ_A...], e.g. 1=0.5,2=-0.5; "
                                    "'%1' is not one")
                         .arg(part);
            return std::nullopt;
        }
        if (id < 1 || id > safety::MultiTorqueGuard::kMaxDrives) {
            *error = QStringLiteral("drive %1: the multi-motor torque frame (0x280) has slots for "
                                    "IDs 1..4 only")
                         .arg(id);
            return std::nullopt;
        }
        if (seen.contains(id)) {
            *error = QStringLiteral("drive %1 is named twice").arg(id);
            return std::nullopt;
        }
        seen.insert(id);
        drives.append({id, iq});
    }
    std::sort(drives.begin(), drives.end(),
              [](const Drive &a, const Drive &b) { return a.id < b.id; });
    return drives;
}

int MultiTorqueControl::run(const ArgParser &parser, const BusOptions &options, Console &console,
                            const QString &command)
{
    const QStringList &pos = parser.positionals();
    if (pos.size() < 2)
        return usage(console, command,
                     QStringLiteral("multi-torque takes ID=IQ_A[,ID=IQ_A...], e.g. 1=0.5,2=-0.5"));
    for (const char *o : {"direction", "max-speed"}) {
        if (parser.isSet(QLatin1String(o)))
            return usage(
                console, command,
                QStringLiteral("--%1 does not go with multi-torque").arg(QLatin1String(o)));
    }
    QString error;
    const std::optional<QVector<Drive>> drives =
        parseDrives(pos.mid(1).join(QLatin1Char(',')), &error); // "1=0.5 2=-0.5" too
    if (!drives)
        return usage(console, command, error);
    const std::optional<MotionLimitOptions> limitOptions = MotionLimitOptions::read(parser, &error);
    if (!limitOptions)
        return usage(console, command, error);
    std::optional<ControlWatch> watch = ControlWatch::read(parser, &error);
    if (!watch)
        return usage(console, command, error);
    const bool json = parser.isSet(QStringLiteral("json"));

    // Everything the guard needs is known before the bus is opened (the link, and each
    // drive's series and generation, which on CAN only --drives tells): a refusal sends no
    // frame at all.
    const protocol::Link link = options.isCan() ? protocol::Link::Can : protocol::Link::Rs485;
    QVector<protocol::Request> torques;
    QMap<int, safety::MultiTorqueDrive> known;
    for (const Drive &d : *drives) {
        const std::optional<bus::DriveIdentity> who = identityOf(options, d.id);
        safety::MultiTorqueDrive m;
        if (who) {
            m.series = who->series;
            m.generation = who->generation;
        }
        const std::optional<safety::SoftLimits> limits = limitOptions->limitsFor(m.series, &error);
        if (!limits)
            return usage(console, command, error);
        m.limits = *limits;
        known.insert(d.id, m);
        const protocol::DecodeContext context{m.series.value_or(protocol::Series::MF),
                                              m.generation.value_or(protocol::Generation::V2_3),
                                              link};
        const protocol::BuildResult built = protocol::build::torque(d.id, d.iqA, context);
        if (!built.ok())
            return usage(console, command,
                         QStringLiteral("drive %1: %2").arg(d.id).arg(built.error.message()));
        torques.append(*built.request);
    }
    LiveBus bus(console, command);
    const safety::MultiTorqueVerdict verdict = safety::MultiTorqueGuard::check(
        torques, link, [&known](int id) { return known.value(id); }, declaredIds(options));
    if (!verdict.allowed()) {
        if (verdict.problem == safety::MultiTorqueProblem::Limit &&
            verdict.verdict.kind != safety::LimitKind::UnknownSeries)
            bus.refused(text::VerdictText::verdict(verdict.verdict, known.value(verdict.id).series),
                        verdict.id);
        else
            bus.error(QStringLiteral("refused: ") + safety::MultiTorqueGuard::text(verdict));
        return kExitRefused;
    }

    if (!bus.open(options))
        return kExitFailure;
    for (const protocol::Request &t : std::as_const(torques))
        watch->arm(bus, t.id, known.value(t.id).limits); // the bus thread bounds them too
    std::optional<bus::MultiTorqueResult> result;
    QObject waiting; // gone on return: a late result finds no `result`
    bus.session().sendMultiTorque(bus::MultiTorqueRequest{torques}, &waiting,
                                  [&result](const bus::MultiTorqueResult &r) { result = r; });
    bus.waitUntil([&result] { return result.has_value(); });
    if (!result) {
        bus.error(QStringLiteral("the multi-motor torque frame did not end in time"));
        return kExitFailure;
    }
    const int status = report(bus, torques, *result, json);
    return watch->followGroup(bus, torques, json, status);
}

int MultiTorqueControl::report(LiveBus &bus, const QVector<protocol::Request> &torques,
                               const bus::MultiTorqueResult &result, bool json)
{
    if (result.refused()) {
        bus.error(QStringLiteral("refused: ") + result.reason);
        return kExitRefused;
    }
    if (!result.attempts) {
        bus.error(result.reason);
        return kExitFailure;
    }
    const QString frame = frameText(torques);
    const protocol::DecodeContext context{protocol::Series::MF, protocol::Generation::V2_3,
                                          protocol::Link::Can};
    QByteArray drives = "[";
    QStringList silent;
    if (!json)
        bus.console().outLine(
            QStringLiteral("Sent multi_torque (0x280, %1) to drives:").arg(frame));
    for (const bus::RequestResult &r : result.drives) {
        const QJsonObject sent = FieldJson::requestFields(r.request, context);
        OrderedJson d;
        d.integer(QStringLiteral("id"), r.request.id).fields(QStringLiteral("sent"), sent);
        if (r.ok() && r.reply)
            d.fields(QStringLiteral("reply"), FieldJson::replyFields(*r.reply));
        else
            d.text(QStringLiteral("status"), QLatin1String(bus::requestStatusName(r.status)));
        drives += (drives.size() > 1 ? "," : "") + d.toJson();
        if (!r.ok())
            silent << QString::number(r.request.id);
        if (json)
            continue;
        QStringList sentText;
        for (const QString &line : ReplyText::lines(sent))
            sentText << line.simplified();
        bus.console().outLine(
            QStringLiteral("  drive %1: %2. %3")
                .arg(r.request.id)
                .arg(sentText.join(QStringLiteral(", ")),
                     r.ok()
                         ? QStringLiteral("Reply:")
                         : QStringLiteral("NO reply (%1).").arg(bus::requestStatusName(r.status))));
        if (r.ok() && r.reply) {
            for (const QString &line :
                 ReplyText::lines(FieldJson::replyFields(*r.reply), QStringLiteral("    ")))
                bus.console().outLine(line);
        }
    }
    drives += ']';
    if (json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), QStringLiteral("multi_torque"))
            .text(QStringLiteral("frame"), frame)
            .raw(QStringLiteral("drives"), drives);
        bus.console().out(o.toJson() + '\n');
    }
    if (silent.isEmpty())
        return kExitOk;
    bus.error(QStringLiteral("drive(s) %1 did not answer the multi-motor torque frame (not in "
                             "their Broadcast Mode, or absent): they may have acted on it all "
                             "the same; stop them with 'lkctl off'")
                  .arg(silent.join(QStringLiteral(", "))));
    return kExitFailure;
}

} // namespace lk::lkctl
