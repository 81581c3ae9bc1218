#include "BusReportGatherer.h"

#include "RequestTracker.h"

#include <bus/BusSession.h>
#include <motor/ModelNameInfo.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QDateTime>

#include <iterator>

namespace lk::ui {

namespace {
using protocol::Command;
constexpr Command kReads[] = {Command::ReadModel, Command::ReadPid, Command::ReadAccel,
                              Command::ReadState1};

void store(record::BusReportDrive &d, const bus::RequestResult &r)
{
    if (const auto *m = replyPayload<protocol::ModelInfo>(r)) {
        d.model = *m;
        if (!d.series)
            d.series = motor::ModelNameInfo::parse(m->motorName).series;
    } else if (const auto *p = replyPayload<protocol::PidGains>(r))
        d.pid = *p;
    else if (const auto *a = replyPayload<protocol::Acceleration>(r))
        d.accelDps2 = a->dps2;
    else if (const auto *s = replyPayload<protocol::State1>(r))
        d.state1 = *s;
    else
        d.problems << QStringLiteral("%1: %2").arg(
            protocol::CommandTable::name(r.request.command),
            r.reason.isEmpty() ? QLatin1String(bus::requestStatusName(r.status)) : r.reason);
}
} // namespace

BusReportGatherer::BusReportGatherer(QObject *parent)
    : QObject(parent), m_tracker(new RequestTracker(this))
{
}

void BusReportGatherer::start(bus::BusSession *session, const QString &toolVersion)
{
    cancel();
    m_tracker->setSession(session);
    m_report = record::BusReport{};
    m_report.createdAt = QDateTime::currentDateTimeUtc();
    m_report.toolVersion = toolVersion;
    if (session) {
        m_report.connection = session->connection().description;
        m_report.baud = session->connection().baud;
    }
    const bus::KnownMotors motors = session ? session->knownMotors() : bus::KnownMotors{};
    for (const bus::KnownMotor &m : motors) { // QMap: ascending ID
        record::BusReportDrive d;
        d.id = m.id;
        d.series = m.series;
        m_report.drives.append(d);
    }
    m_total = int(m_report.drives.size() * std::size(kReads));
    m_outstanding = m_total;
    if (m_total == 0) {
        emit finished(m_report);
        return;
    }
    for (int i = 0; i < m_report.drives.size(); ++i) {
        for (Command c : kReads) {
            m_tracker->send(*protocol::build::plain(c, m_report.drives[i].id).request,
                            [this, i](const bus::RequestResult &r) {
                                store(m_report.drives[i], r);
                                requestDone();
                            });
        }
    }
    emit progress(0, m_total);
}

void BusReportGatherer::cancel()
{
    m_tracker->forgetAll();
    m_outstanding = 0;
}

void BusReportGatherer::requestDone()
{
    if (m_outstanding <= 0)
        return;
    --m_outstanding;
    emit progress(m_total - m_outstanding, m_total);
    if (m_outstanding == 0)
        emit finished(m_report);
}

} // namespace lk::ui
