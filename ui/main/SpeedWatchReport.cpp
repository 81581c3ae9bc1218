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

SpeedWatchReport::SpeedWatchReport(bus::BusSession *session, BusModel *model,
                                   MessageBanner *banner, QObject *parent)
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
    showEntry(trip.id, text.toHtmlEscaped(), v235 && trip.stopAcknowledged());
    emit driveStopped(trip.id, tr("Stopped by the speed watch at %1: %2")
                                   .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")),
                                        text));
}

void SpeedWatchReport::showEntry(int id, const QString &html, bool offerMaxSpeed)
{
    QString text = QStringLiteral("<b>%1</b> %2").arg(tr("Speed watch:"), html);
    if (offerMaxSpeed) {
        const double limit = m_trips.value(id).limitDps;
        text += QStringLiteral(" <a href=\"%1\">%2</a>")
                    .arg(maxSpeedLink(),
                         tr("Set the drive's own Max Speed (0x9A) to %1 dps (RAM)")
                             .arg(Format::number(limit, 0))
                             .toHtmlEscaped());
    }
    m_banner->setEntry(entryKey(id), MessageBanner::Level::Error, text);
}

void SpeedWatchReport::setDriveMaxSpeed(int id, double dps)
{
    const auto built = protocol::build::writeParam(id, protocol::ParamId::MaxSpeed, dps, false);
    if (!m_session || !built.ok())
        return;
    const QString before = describe(m_trips.value(id)).toHtmlEscaped();
    showEntry(id, before + QLatin1Char(' ') + tr("Writing Max Speed\u2026").toHtmlEscaped(), false);
    m_session->send(*built.request, this, [this, id, dps, before](const bus::RequestResult &r) {
        const auto *ack = r.ok() ? std::get_if<protocol::ParamWriteResult>(&r.reply->payload)
                                 : nullptr;
        if (!ack || !ack->succeeded()) {
            const QString why = ack ? tr("the drive refused the write")
                                    : tr("no confirmation (%1)").arg(r.reason);
            showEntry(id,
                      before + QLatin1Char(' ') +
                          tr("Max Speed not set: %1; nothing was verified.").arg(why).toHtmlEscaped(),
                      true);
            return;
        }
        const auto read = protocol::build::readParam(id, protocol::ParamId::MaxSpeed);
        m_session->send(*read.request, this,
                        [this, id, dps](const bus::RequestResult &back) {
                            const auto *v =
                                back.ok() ? std::get_if<protocol::ParameterValue>(
                                                &back.reply->payload)
                                          : nullptr;
                            onMaxSpeedRead(id, dps,
                                           v ? Format::number(v->asInt32() / 100.0, 2)
                                             : QString());
                        });
    });
}

void SpeedWatchReport::onMaxSpeedRead(int id, double dps, const QString &readBack)
{
    const QString before = describe(m_trips.value(id));
    QString result;
    if (readBack.isEmpty())
        result = tr("Max Speed written (the drive confirmed the RAM write), but the read-back "
                    "got no answer: not verified.");
    else if (std::abs(readBack.toDouble() - dps) < 0.005)
        result = tr("Max Speed set: the drive reads back %1 dps (RAM: until it is powered off). "
                    "It bounds the drive's speed and position commands; whether it also bounds "
                    "torque and open loop is not documented, so the speed watch stays on.")
                     .arg(readBack);
    else
        result = tr("Max Speed written, but the drive reads back %1 dps instead of %2 dps.")
                     .arg(readBack, Format::number(dps, 2));
    qCInfo(lcSpeedWatch).noquote() << "drive" << id << result;
    showEntry(id, (before + QLatin1Char(' ') + result).toHtmlEscaped(), readBack.isEmpty());
}

} // namespace lk::ui
