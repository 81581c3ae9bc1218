#include "FleetRestore.h"

#include <bus/BusSession.h>
#include <protocol/Command.h>

namespace lk::fleet {

using Outcome = DriveReport::Outcome;

const char *DriveReport::outcomeName(Outcome o)
{
    switch (o) {
    case Outcome::Verified:
        return "verified";
    case Outcome::Written:
        return "written";
    case Outcome::Unchanged:
        return "unchanged";
    case Outcome::Differs:
        return "differs";
    case Outcome::Refused:
        return "refused";
    case Outcome::Failed:
        break;
    }
    return "failed";
}

FleetRestore::FleetRestore(bus::BusSession *session, QObject *parent)
    : QObject(parent), m_session(session), m_reader(session)
{
    connect(&m_reader, &FleetReader::driveRead, this,
            [this](const DriveSnapshot &, int done, int total) {
                if (m_preparing)
                    emit progress(done, total);
            });
    connect(&m_reader, &FleetReader::finished, this, [this] {
        if (!m_preparing) {
            onReadBack();
            return;
        }
        m_preparing = false;
        QList<int> planned;
        for (const Job &job : std::as_const(m_jobs)) {
            DriveSnapshot target;
            for (const DriveSnapshot &s : m_reader.snapshots()) {
                if (s.id() == job.targetId)
                    target = s;
            }
            target.identity.id = job.targetId;
            RestorePlan plan = RestorePlan::make(job.source, target);
            if (planned.contains(job.targetId)) { // one source per target
                plan.refusal = Refusal{QStringLiteral("map"),
                                       QStringLiteral("drive %1 is the target of more than one "
                                                      "source")
                                           .arg(job.targetId)};
                plan.changes.clear();
            }
            planned << job.targetId;
            m_plans << plan;
        }
        m_busy = false;
        emit prepared();
    });
}

void FleetRestore::prepare(const QVector<Job> &jobs)
{
    m_jobs = jobs;
    m_plans.clear();
    m_reports.clear();
    QVector<int> ids;
    for (const Job &job : jobs) {
        if (!ids.contains(job.targetId))
            ids << job.targetId;
    }
    m_preparing = true;
    m_busy = true;
    m_reader.start(ids);
}

QVector<DriveSnapshot> FleetRestore::undo() const
{
    QVector<DriveSnapshot> out;
    for (const RestorePlan &p : m_plans) {
        if (p.target.identified)
            out << p.target;
    }
    return out;
}

void FleetRestore::execute(bool rom)
{
    m_rom = rom;
    m_reports.clear();
    m_busy = true;
    nextPlan();
}

void FleetRestore::nextPlan()
{
    if (m_reports.size() >= m_plans.size()) {
        m_busy = false;
        emit finished();
        return;
    }
    const RestorePlan &plan = m_plans.at(m_reports.size());
    m_report = DriveReport();
    m_report.sourceId = plan.source.id();
    m_report.targetId = plan.targetId();
    m_report.refusal = plan.refusal;
    m_report.changes = plan.changes;
    const DriveIdentity &to = plan.target.identity;
    if (!plan.refusal && m_rom && !FleetCatalog::hasRom(to.generation, to.link)) {
        // The last gate before the bus: a CAN V2.36 drive has nothing that writes ROM.
        m_report.refusal = Refusal{
            QStringLiteral("rom"),
            QStringLiteral("drive %1 is CAN V2.36: its control parameters (0xC1) are RAM only, "
                           "there is no ROM write; nothing was sent")
                .arg(plan.targetId())};
    }
    if (m_report.refusal) {
        endDrive(Outcome::Refused);
    } else if (plan.changes.isEmpty() && !m_rom) {
        m_report.after = plan.target;
        endDrive(Outcome::Unchanged);
    } else {
        // The RAM already holds the values when nothing changes: straight to ROM.
        startStage(plan.changes.isEmpty() ? Stage::Rom : Stage::Ram);
    }
}

void FleetRestore::startStage(Stage stage)
{
    m_stage = stage;
    const RestorePlan &plan = m_plans.at(m_reports.size());
    if (stage == Stage::ReadBack || stage == Stage::RomReadBack) {
        m_reader.start({plan.targetId()});
        return;
    }
    const DriveIdentity &to = plan.target.identity;
    m_frames = FleetCatalog::writes(plan.targetId(), to.generation, plan.source.valueMap(),
                                    plan.changedKeys(), stage == Stage::Rom, to.link);
    sendNextFrame();
}

void FleetRestore::sendNextFrame()
{
    if (m_frames.isEmpty()) {
        if (m_stage == Stage::Ram)
            m_report.ramWritten = true;
        else
            m_report.romAcknowledged = true;
        startStage(m_stage == Stage::Ram ? Stage::ReadBack : Stage::RomReadBack);
        return;
    }
    if (!m_session) {
        m_report.reason = QStringLiteral("the bus was closed");
        endDrive(Outcome::Failed);
        return;
    }
    const ParamFrame frame = m_frames.takeFirst();
    const bool rom = m_stage == Stage::Rom;
    if (rom)
        ++m_report.romFramesSent;
    // A ROM write is sent once, never repeated: the drive may have stored it already.
    m_session->send(
        frame.request, this, [this, frame](const bus::RequestResult &r) { onFrame(frame, r); },
        bus::Priority::Operator, rom ? 0 : -1);
}

void FleetRestore::onFrame(const ParamFrame &frame, const bus::RequestResult &r)
{
    const auto *flag =
        r.reply ? std::get_if<protocol::ParamWriteResult>(&r.reply->payload) : nullptr;
    if (r.ok() && (!flag || flag->succeeded())) {
        sendNextFrame();
        return;
    }
    const QString command = protocol::CommandTable::name(frame.request.command);
    const QString what =
        r.ok() ? QStringLiteral("was refused by the drive (failure flag)")
               : QStringLiteral("got no reply (%1%2)")
                     .arg(QLatin1String(bus::requestStatusName(r.status)),
                          r.reason.isEmpty() ? QString() : QStringLiteral(": ") + r.reason);
    m_report.reason =
        QStringLiteral("%1 of %2 %3").arg(command, frame.keys.join(QLatin1Char(',')), what);
    if (m_stage == Stage::Rom)
        m_report.reason +=
            QStringLiteral("; it was sent once and is not repeated, so whether the drive stored "
                           "it is not known; %1 further ROM frame(s) were not sent")
                .arg(m_frames.size());
    m_frames.clear();
    endDrive(Outcome::Failed);
}

void FleetRestore::onReadBack()
{
    const RestorePlan &plan = m_plans.at(m_reports.size());
    const DriveSnapshot after = m_reader.snapshots().value(0);
    m_report.after = after;
    if (!after.complete()) {
        m_report.reason = QStringLiteral("the read-back failed: %1").arg(after.failure);
        endDrive(Outcome::Failed);
        return;
    }
    const DriveIdentity &to = plan.target.identity;
    for (const FleetParam &p : FleetCatalog::params(to.generation, to.link)) {
        const qint64 wrote = plan.source.values.value(p.key).value;
        const qint64 reads = after.values.value(p.key).value;
        if (p.restorable && wrote != reads)
            m_report.mismatches
                << QStringLiteral("%1: wrote %2, reads %3").arg(p.key).arg(wrote).arg(reads);
    }
    if (!m_report.mismatches.isEmpty()) {
        endDrive(Outcome::Differs); // never on to ROM
        return;
    }
    if (m_stage == Stage::ReadBack) {
        if (!FleetCatalog::hasRom(to.generation, to.link))
            m_report.notes << QStringLiteral("RAM only: CAN V2.36 keeps its control parameters "
                                             "in RAM (0xC1), they are lost at power-off; "
                                             "nothing was written to ROM");
        if (m_rom)
            startStage(Stage::Rom);
        else
            endDrive(Outcome::Verified);
        return;
    }
    if (to.generation == protocol::Generation::V2_3) {
        const QString v23 = to.link == protocol::Link::Can
                                ? QStringLiteral("the old CAN generation (protocol V2.3)")
                                : QStringLiteral("protocol V2.3");
        m_report.notVerified
            << QStringLiteral("ROM: %1 has no command that reads ROM; RAM was read back equal "
                              "after write_pid_rom was acknowledged")
                   .arg(v23)
            << QStringLiteral("accel_dps2: RAM only, %1 has no ROM command for it").arg(v23);
        endDrive(Outcome::Written);
        return;
    }
    endDrive(Outcome::Verified);
}

void FleetRestore::endDrive(Outcome outcome)
{
    m_report.outcome = outcome;
    m_reports << m_report;
    emit progress(int(m_reports.size()), int(m_plans.size()));
    nextPlan();
}

} // namespace lk::fleet
