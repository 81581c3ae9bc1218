#include "FleetReader.h"

#include <bus/BusSession.h>
#include <bus/MotorRegistry.h>
#include <protocol/RequestBuilder.h>

namespace lk::fleet {

namespace {
QString failureText(const bus::RequestResult &r)
{
    return QStringLiteral("%1: %2%3")
        .arg(protocol::CommandTable::name(r.request.command),
             QLatin1String(bus::requestStatusName(r.status)),
             r.reason.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(r.reason));
}
} // namespace

FleetReader::FleetReader(bus::BusSession *session, QObject *parent)
    : QObject(parent), m_session(session)
{
}

void FleetReader::start(const QVector<int> &ids)
{
    ++m_run;
    m_ids = ids;
    m_snapshots.clear();
    m_outstanding = 0;
    m_running = true;
    m_cancelled = false;
    readNext();
}

void FleetReader::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    if (m_outstanding == 0) { // between drives: nothing to wait for
        m_running = false;
        emit finished();
    }
}

void FleetReader::readNext()
{
    if (m_cancelled || m_snapshots.size() >= m_ids.size() || !m_session) {
        m_running = false;
        emit finished();
        return;
    }
    m_current = DriveSnapshot();
    m_current.identity.id = m_ids.at(m_snapshots.size());
    m_current.readAt = QDateTime::currentDateTimeUtc();
    m_failures.clear();
    if (m_session->connection().link == protocol::Link::Can) {
        identifyOnCan();
        return;
    }
    m_outstanding = 1;
    const quint64 run = m_run;
    m_session->send(*protocol::build::plain(protocol::Command::ReadModel, m_current.id()).request,
                    this, [this, run](const bus::RequestResult &r) {
                        if (run == m_run)
                            onModel(r);
                    });
}

void FleetReader::onModel(const bus::RequestResult &r)
{
    m_outstanding = 0;
    const auto *model = r.reply ? std::get_if<protocol::ModelInfo>(&r.reply->payload) : nullptr;
    if (!r.ok() || !model) {
        m_failures << failureText(r);
        finishDrive();
        return;
    }
    DriveIdentity &who = m_current.identity;
    who.driverName = model->driverName;
    who.motorName = model->motorName;
    who.series = bus::MotorRegistry::seriesOf(*model);
    who.generation = model->generation;
    who.hardwareRaw = model->hardwareRaw;
    who.firmwareRaw = model->firmwareRaw;
    who.uniqueId = model->motorId;
    m_current.identified = true;
    if (who.series && m_session)
        m_session->setSeries(who.id, *who.series); // replies decode by it (MS: power)
    readValues();
}

void FleetReader::identifyOnCan()
{
    // CAN has no read_model (0x12): who the drive is comes from the user's word alone
    // (BusSession::setDriveIdentity), and the file will say it was declared. A reply could
    // hint the generation, but never the series a restore must match.
    DriveIdentity &who = m_current.identity;
    const std::optional<bus::DriveIdentity> declared = m_session->driveIdentity(who.id);
    if (!declared) {
        m_failures << QStringLiteral("CAN has no model read (0x12), and drive %1's series and "
                                     "generation were not declared, so its parameters are not "
                                     "known; nothing was sent to it")
                          .arg(who.id);
        // Later, as a reply would come: start() never finishes before its caller listens.
        const quint64 run = m_run;
        m_outstanding = 1;
        QMetaObject::invokeMethod(
            this,
            [this, run] {
                if (run != m_run)
                    return;
                m_outstanding = 0;
                finishDrive();
            },
            Qt::QueuedConnection);
        return;
    }
    who.link = protocol::Link::Can;
    who.declared = true;
    who.series = declared->series;
    who.generation = declared->generation;
    who.gearRatio = declared->gearRatio;
    m_current.identified = true;
    readValues();
}

void FleetReader::readValues()
{
    const DriveIdentity &who = m_current.identity;
    const QVector<protocol::Request> reads =
        FleetCatalog::reads(who.id, who.generation, who.series, who.link);
    m_outstanding = int(reads.size());
    const quint64 run = m_run;
    for (const protocol::Request &request : reads) {
        m_session->send(request, this, [this, run](const bus::RequestResult &result) {
            if (run == m_run)
                onValue(result);
        });
    }
    if (reads.isEmpty())
        finishDrive();
}

void FleetReader::onValue(const bus::RequestResult &r)
{
    if (r.ok() && r.reply) {
        const ValueMap values = FleetCatalog::decode(*r.reply);
        const QDateTime now = QDateTime::currentDateTimeUtc();
        for (auto it = values.begin(); it != values.end(); ++it)
            m_current.values.insert(it.key(), ReadValue{it.value(), now});
    } else {
        m_failures << failureText(r);
    }
    if (--m_outstanding == 0)
        finishDrive();
}

void FleetReader::finishDrive()
{
    ValueMap raw = m_current.valueMap();
    FleetCatalog::joinHalves(raw);
    const QString angle = QStringLiteral("max_angle_raw");
    // V2.35's int64 comes in two halves; CAN V2.36's int32 is read whole, with its own time.
    if (raw.contains(angle) && m_current.values.contains(QStringLiteral("max_angle_high"))) {
        const QDateTime at = m_current.values.value(QStringLiteral("max_angle_high")).readAt;
        m_current.values.insert(angle, ReadValue{raw.value(angle), at});
    }
    m_current.values.remove(QStringLiteral("max_angle_low"));
    m_current.values.remove(QStringLiteral("max_angle_high"));
    if (m_failures.isEmpty() && !m_current.complete())
        m_failures << QStringLiteral("the drive did not report every parameter");
    m_current.failure = m_failures.join(QStringLiteral("; "));
    m_snapshots << m_current;
    emit driveRead(m_current, int(m_snapshots.size()), int(m_ids.size()));
    readNext();
}

} // namespace lk::fleet
