#include "SpeedWatchReport.h"

#include <panels/BusModel.h>
#include <panels/Format.h>
#include <panels/MessageBanner.h>

#include <bus/BusSession.h>
#include <bus/SpeedWatch.h>
#include <protocol/Parameter.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QDateTime>
#include <QtCore/QLoggingCategory>

#include <cmath>

Q_LOGGING_CATEGORY(lcSpeedWatch, "lk.studio.watch")

namespace lk::ui {

using protocol::Command;

SpeedWatchReport::SpeedWatchReport(bus::BusSession *session, BusModel *model, MessageBanner *banner,
                                   QObject *parent)
    : QObject(parent), m_session(session), m_model(model), m_banner(banner)
{
    connect(session, &bus::BusSession::speedWatchTripped, this, &SpeedWatchReport::onTripped);
    connect(banner, &MessageBanner::entryLinkActivated, this,
            [this](const QString &key, const QString &link) {
                for (auto it = m_trips.cbegin(); it != m_trips.cend(); ++it) {
                    if (key == entryKey(it.key()) && link == maxSpeedLink())
                        setDriveMaxSpeed(it.key(), it->limitDps);
                }
            });
}

QString SpeedWatchReport::describe(const bus::SpeedWatchTrip &t)
{
    const QString mode = t.mode == Command::OpenLoop ? tr("open loop (0xA0)") : tr("torque (0xA1)");
    const QString limit = t.source == bus::SpeedWatchSource::SoftLimit
                              ? tr("your speed limit %1 dps").arg(Format::number(t.limitDps, 0))
                              : tr("the series' top speed %1 dps (no soft limit given)")
                                    .arg(Format::number(t.limitDps, 0));
    const QString what =
        tr("Drive %1 reached %2 dps under %3, past %4 (stopped above %5 dps).")
            .arg(t.id)
            .arg(Format::number(t.speedDps, 0), mode, limit, Format::number(t.thresholdDps, 0));
    if (t.stopAcknowledged())
        return what + QLatin1Char(' ') +
               tr("Motor Stop (0x81) sent and acknowledged %1 ms after that reading; the drive "
                  "coasts to a stop.")
                   .arg(Format::number(t.reactionMs(), 0));
    return what + QLatin1Char(' ') +
           tr("Motor Stop (0x81) sent but not acknowledged (%1): the drive may still be turning; "
              "the watch stops it again while it reads too fast. Press Esc to stop every drive.")
               .arg(t.stopReason);
}

void SpeedWatchReport::onTripped(const bus::SpeedWatchTrip &trip)
{
    m_trips.insert(trip.id, trip);
    const QString text = describe(trip);
    qCWarning(lcSpeedWatch).noquote()
        << QDateTime::currentDateTime().toString(Qt::ISODateWithMs) << "speed watch:" << text;
    const DriveRecord *d = m_model->drive(trip.id);
    const bool v235 = d && d->generation() == protocol::Generation::V2_35;
    showEntry(trip.id, text, QString(), v235 && trip.stopAcknowledged());
    emit driveStopped(trip.id,
                      tr("Stopped by the speed watch at %1: %2")
                          .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), text));
}

void SpeedWatchReport::showEntry(int id, const QString &trip, const QString &detail,
                                 bool offerMaxSpeed)
{
    QString text = QStringLiteral("<b>%1</b> %2")
                       .arg(tr("Speed watch:").toHtmlEscaped(), trip.toHtmlEscaped());
    if (!detail.isEmpty())
        text += QLatin1Char(' ') + detail.toHtmlEscaped();
    if (offerMaxSpeed) {
        const double limit = m_trips.value(id).limitDps;
        text += QStringLiteral(" <a href=\"%1\">%2</a>")
                    .arg(maxSpeedLink(),
                         tr("Read the drive's own Max Speed (ParamID 0x9A) and set it to %1 "
                            "dps (RAM)")
                             .arg(Format::number(limit, 0))
                             .toHtmlEscaped());
    }
    m_banner->setEntry(entryKey(id), MessageBanner::Level::Error, text);
}

void SpeedWatchReport::setDriveMaxSpeed(int id, double dps)
{
    // Never write what was not read: the drive's own Max Speed is read first, and only a
    // value above the soft limit is replaced.
    if (!m_session || !m_trips.contains(id))
        return;
    showEntry(id, describe(m_trips.value(id)), tr("Reading the drive's Max Speed\u2026"), false);
    const auto read = protocol::build::readParam(id, protocol::ParamId::MaxSpeed);
    m_session->send(*read.request, this, [this, id, dps](const bus::RequestResult &r) {
        const std::optional<double> held = maxSpeedOf(r);
        if (!held) {
            finish(id,
                   tr("The drive's Max Speed could not be read (%1): nothing was written.")
                       .arg(r.ok() ? tr("unexpected reply") : r.reason),
                   true);
            return;
        }
        if (*held <= dps) {
            finish(id,
                   tr("The drive's own Max Speed is %1 dps, not above your limit: nothing was "
                      "written.")
                       .arg(Format::number(*held, 2)),
                   false);
            return;
        }
        writeMaxSpeed(id, *held, dps);
    });
}

std::optional<double> SpeedWatchReport::maxSpeedOf(const bus::RequestResult &r)
{
    const auto *v =
        r.ok() && r.reply ? std::get_if<protocol::ParameterValue>(&r.reply->payload) : nullptr;
    if (!v || v->id() != protocol::ParamId::MaxSpeed)
        return std::nullopt;
    return v->asInt32() / 100.0; // 0.01 dps (docs/V2.35.md section 6)
}

void SpeedWatchReport::writeMaxSpeed(int id, double was, double dps)
{
    const auto built = protocol::build::writeParam(id, protocol::ParamId::MaxSpeed, dps, false);
    if (!built.ok())
        return;
    const QString read = tr("The drive's Max Speed read %1 dps.").arg(Format::number(was, 2));
    showEntry(id, describe(m_trips.value(id)), read + QLatin1Char(' ') + tr("Writing\u2026"),
              false);
    m_session->send(*built.request, this, [this, id, dps, read](const bus::RequestResult &r) {
        const auto *ack = r.ok() && r.reply
                              ? std::get_if<protocol::ParamWriteResult>(&r.reply->payload)
                              : nullptr;
        if (!ack || !ack->succeeded()) {
            // A RAM write is not repeated on its own: the user may click again.
            const QString why =
                ack ? tr("the drive refused the write") : tr("no confirmation (%1)").arg(r.reason);
            finish(id,
                   read + QLatin1Char(' ') +
                       tr("Max Speed not confirmed: %1; nothing was verified.").arg(why),
                   true);
            return;
        }
        const auto back = protocol::build::readParam(id, protocol::ParamId::MaxSpeed);
        m_session->send(*back.request, this, [this, id, dps, read](const bus::RequestResult &b) {
            finish(id, read + QLatin1Char(' ') + readBackText(maxSpeedOf(b), dps), !maxSpeedOf(b));
        });
    });
}

QString SpeedWatchReport::readBackText(std::optional<double> readBack, double dps)
{
    if (!readBack)
        return tr("Max Speed written (the drive confirmed the RAM write), but the read-back "
                  "got no answer: not verified.");
    if (std::abs(*readBack - dps) < 0.005)
        return tr("Max Speed set: the drive reads back %1 dps (RAM: until it is powered off). "
                  "It bounds the drive's speed and position commands; whether it also bounds "
                  "torque and open loop is not documented, so the speed watch stays on.")
            .arg(Format::number(*readBack, 2));
    return tr("Max Speed written, but the drive reads back %1 dps instead of %2 dps.")
        .arg(Format::number(*readBack, 2), Format::number(dps, 2));
}

void SpeedWatchReport::finish(int id, const QString &result, bool offerAgain)
{
    qCInfo(lcSpeedWatch).noquote() << "drive" << id << result;
    showEntry(id, describe(m_trips.value(id)), result, offerAgain);
}

} // namespace lk::ui
