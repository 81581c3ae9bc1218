#include "BusReportGatherer.h"

#include "RequestTracker.h"

#include <bus/BusSession.h>
#include <motor/ModelNameInfo.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QDateTime>

namespace lk::ui {

namespace {
using protocol::Command;
using protocol::Generation;

void noteProblem(record::BusReportDrive &d, const bus::RequestResult &r)
{
    QString what = protocol::CommandTable::name(r.request.command);
    if (const auto *p = std::get_if<protocol::ParamRead>(&r.request.payload))
        what += QLatin1Char(' ') + protocol::ParamTable::name(protocol::ParamId(p->paramId));
    d.problems << QStringLiteral("%1: %2").arg(
        what, r.reason.isEmpty() ? QLatin1String(bus::requestStatusName(r.status)) : r.reason);
}

void store(record::BusReportDrive &d, const bus::RequestResult &r)
{
    if (const auto *m = replyPayload<protocol::ModelInfo>(r)) {
        d.model = *m;
        d.generation = m->generation;
        if (!d.series)
            d.series = motor::ModelNameInfo::parse(m->motorName).series;
    } else if (const auto *p = replyPayload<protocol::PidGains>(r))
        d.pid = *p;
    else if (const auto *a = replyPayload<protocol::Acceleration>(r))
        d.accelDps2 = a->dps2;
    else if (const auto *v = replyPayload<protocol::ParameterValue>(r))
        d.params.append(*v);
    else if (const auto *s = replyPayload<protocol::State1>(r))
        d.state1 = d.generation ? s->as(*d.generation) : *s; // the layout of its generation
    else
        noteProblem(d, r);
}
} // namespace

BusReportGatherer::BusReportGatherer(QObject *parent)
    : QObject(parent), m_tracker(new RequestTracker(this))
{
}

QVector<protocol::Request> BusReportGatherer::readsFor(int id, std::optional<Generation> generation)
{
    QVector<protocol::Request> reads;
    if (generation == Generation::V2_3) {
        reads << *protocol::build::plain(Command::ReadPid, id).request
              << *protocol::build::plain(Command::ReadAccel, id).request;
    } else if (generation == Generation::V2_35) {
        // No 0x30/0x33 there: the gains and limits are parameters (docs/V2.35.md section 6).
        for (const protocol::ParamInfo &p : protocol::ParamTable::all())
            reads << *protocol::build::readParam(id, p.id).request;
    }
    reads << *protocol::build::plain(Command::ReadState1, id).request;
    return reads;
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
    m_known.clear();
    m_total = 0;
    for (const bus::KnownMotor &m : motors) { // QMap: ascending ID
        record::BusReportDrive d;
        d.id = m.id;
        d.series = m.series;
        // The session's generation is only known when it read the model.
        const std::optional<Generation> known =
            m.model ? std::optional<Generation>(m.generation) : std::nullopt;
        m_known.append(known);
        m_report.drives.append(d);
        m_total += 1 + int(readsFor(m.id, known).size());
    }
    m_outstanding = m_total;
    if (m_total == 0) {
        emit finished(m_report);
        return;
    }
    // The model first: its generation decides what else the drive is asked.
    for (int i = 0; i < m_report.drives.size(); ++i) {
        m_tracker->send(*protocol::build::plain(Command::ReadModel, m_report.drives[i].id).request,
                        [this, i](const bus::RequestResult &r) {
                            store(m_report.drives[i], r);
                            readByGeneration(i);
                            requestDone();
                        });
    }
    emit progress(0, m_total);
}

void BusReportGatherer::readByGeneration(int index)
{
    record::BusReportDrive &d = m_report.drives[index];
    if (!d.generation)
        d.generation = m_known.value(index);
    if (!d.generation)
        d.problems << QStringLiteral("protocol generation unknown (no model was read): gains "
                                     "and parameters were not asked for");
    const QVector<protocol::Request> reads = readsFor(d.id, d.generation);
    // The estimate made at start was for the session's generation: correct it.
    const int planned = int(readsFor(d.id, m_known.value(index)).size());
    m_total += int(reads.size()) - planned;
    m_outstanding += int(reads.size()) - planned;
    for (const protocol::Request &request : reads) {
        m_tracker->send(request, [this, index](const bus::RequestResult &r) {
            store(m_report.drives[index], r);
            requestDone();
        });
    }
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
