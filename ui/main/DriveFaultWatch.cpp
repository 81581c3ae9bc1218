#include "DriveFaultWatch.h"

#include "CommandedMotion.h"

#include <panels/BusModel.h>
#include <panels/Format.h>
#include <panels/MessageBanner.h>

#include <QtCore/QLoggingCategory>

#include <cmath>
#include <optional>

Q_LOGGING_CATEGORY(lcHealth, "lk.studio.health")

namespace lk::ui {

using F = bus::TelemetryField;

namespace {
constexpr int kEventsKept = 6;
// Commands this small may read as 0 while the drive follows them: not judged.
constexpr double kMinSpeedDps = 10;
constexpr double kMinTorqueA = 0.1;
constexpr int kMinPower = 50;

QString flagsText(int flags, std::optional<protocol::Generation> generation)
{
    return QStringLiteral("%1 (0x%2)")
        .arg(Format::errorFlagsText(flags, generation))
        .arg(flags, 2, 16, QLatin1Char('0'));
}
} // namespace

DriveFaultWatch::DriveFaultWatch(BusModel *model, CommandedMotion *motion, MessageBanner *banner,
                                 QObject *parent)
    : QObject(parent), m_model(model), m_motion(motion), m_banner(banner)
{
}

void DriveFaultWatch::onTelemetry(const bus::TelemetryBatch &batch)
{
    // The fields each drive had been read with before this batch: a field is judged from its
    // second reading on. The first 0x9A of a drive is the scan's probe, decoded before its
    // model (and so its generation) was read: a V2.35 drive's shows 0.9 V and wrong flags.
    QMap<int, bus::TelemetryFields> before;
    for (const bus::TelemetrySample &s : batch) {
        if (!m_model->drive(s.id))
            continue; // not a drive of this bus (a late reply after a rescan)
        Drive &d = m_drives[s.id];
        judgeStopped(s, d);
        if (!before.contains(s.id))
            before.insert(s.id, d.polled);
        d.polled |= s.fields;
    }
    for (auto it = before.cbegin(); it != before.cend(); ++it)
        judgeHealth(it.key(), m_drives[it.key()], *it);
}

void DriveFaultWatch::judgeHealth(int id, Drive &d, bus::TelemetryFields judged)
{
    const DriveRecord &r = *m_model->drive(id);
    DriveHealth h = DriveHealth::of(r);
    if (!judged.testFlag(F::Voltage))
        h.lowVoltage = h.highVoltage = false;
    if (!judged.testFlag(F::ErrorState))
        h.faults = false;
    const int flags = h.faults ? r.latest.errorState : 0; // judged as DriveHealth does
    const int appeared = flags & ~d.errorState;
    bool changed = false;
    if (appeared) {
        note(id, d, tr("fault flags %1").arg(flagsText(flags, r.generation())), true);
        changed = true;
    } else if (flags == 0 && d.errorState != 0) {
        note(id, d, tr("fault flags clear"), false);
        changed = true;
    }
    d.errorState = flags;
    if (h.hot != d.health.hot) {
        note(id, d,
             h.hot ? tr("temperature %1 °C (hot from %2 °C)")
                         .arg(r.latest.temperatureC)
                         .arg(DriveHealth::kHotTemperatureC)
                   : tr("temperature back below %1 °C (%2 °C)")
                         .arg(DriveHealth::kHotTemperatureC)
                         .arg(r.latest.temperatureC),
             h.hot);
        changed = true;
    }
    if (h.voltageOut() != d.health.voltageOut()) {
        const QString volts = Format::withUnit(r.latest.voltageV, 2, QStringLiteral("V"));
        const QString range = DriveHealth::supplyRangeText(r).value_or(QString());
        note(id, d,
             h.voltageOut() ? tr("supply %1 outside the series' range (%2)").arg(volts, range)
                            : tr("supply back in range (%1)").arg(volts),
             h.voltageOut());
        changed = true;
    }
    d.health = h;
    // Drives switch themselves off on a protection: a commanded drive has stopped.
    if (appeared && m_motion->last(id) && !d.stopReported) {
        d.stopReported = true;
        const QString why = tr("fault flags %1").arg(flagsText(flags, r.generation()));
        note(id, d, tr("stopped by itself: %1").arg(why), true);
        emit driveStopped(id,
                          tr("Drive %1 stopped by itself at %2: %3. It no longer follows %4.")
                              .arg(id)
                              .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), why,
                                   CommandedMotion::describe(m_motion->last(id)->request)));
    }
    if (changed)
        show(id, d);
}

std::optional<QString> DriveFaultWatch::notMovingReason(const bus::TelemetrySample &s,
                                                        const protocol::Request &r) const
{
    if (s.has(F::MotorOn) && !s.motorOn)
        return tr("it reads motor off");
    if (const auto *v = std::get_if<protocol::SpeedCommand>(&r.payload);
        v && std::abs(v->speedDps()) >= kMinSpeedDps && s.has(F::Speed))
        return s.speedDps == 0 ? tr("it reads 0 dps under a speed command") : QString();
    if (const auto *t = std::get_if<protocol::TorqueCommand>(&r.payload);
        t && std::abs(t->iqA()) >= kMinTorqueA && s.has(F::IqA))
        return s.iqA == 0 ? tr("it reads no current under a torque command") : QString();
    if (const auto *p = std::get_if<protocol::OpenLoopCommand>(&r.payload);
        p && std::abs(p->power) >= kMinPower && s.has(F::Power))
        return s.power == 0 ? tr("it reads no power under an open-loop command") : QString();
    return std::nullopt; // this reading says nothing about it
}

void DriveFaultWatch::judgeStopped(const bus::TelemetrySample &s, Drive &d)
{
    const std::optional<CommandedMotion::Entry> last = m_motion->last(s.id);
    if (!last) {
        d.commandAt = {};
        d.stopReported = false;
        return;
    }
    if (last->sentAt != d.commandAt) { // a new command: judged afresh
        d.commandAt = last->sentAt;
        d.firstReadingS = s.time;
        d.stillSinceS = -1;
        d.stopReported = false;
    }
    if (d.stopReported)
        return;
    const std::optional<QString> why = notMovingReason(s, last->request);
    if (!why)
        return;
    if (why->isEmpty() || s.time - d.firstReadingS < kStartGraceS) {
        d.stillSinceS = -1;
        return;
    }
    if (d.stillSinceS < 0)
        d.stillSinceS = s.time;
    if (s.time - d.stillSinceS < kStoppedForS)
        return;
    d.stopReported = true;
    note(s.id, d,
         tr("stopped by itself: %1 (last command %2)")
             .arg(*why, CommandedMotion::describe(last->request)),
         true);
    show(s.id, d);
    emit driveStopped(s.id, tr("Drive %1 stopped by itself at %2: %3. It no longer follows %4.")
                                .arg(s.id)
                                .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")),
                                     *why, CommandedMotion::describe(last->request)));
}

void DriveFaultWatch::note(int id, Drive &d, const QString &event, bool warning)
{
    const QDateTime now = QDateTime::currentDateTime();
    d.events.append(QStringLiteral("%1 %2").arg(now.toString(QStringLiteral("HH:mm:ss")), event));
    while (d.events.size() > kEventsKept)
        d.events.removeFirst();
    const QString line =
        QStringLiteral("%1 drive %2: %3").arg(now.toString(Qt::ISODateWithMs)).arg(id).arg(event);
    if (warning)
        qCWarning(lcHealth).noquote() << line;
    else
        qCInfo(lcHealth).noquote() << line;
}

void DriveFaultWatch::show(int id, const Drive &d)
{
    const DriveRecord *r = m_model->drive(id);
    if (!r)
        return;
    const QStringList problems = d.health.problems(*r);
    MessageBanner::Level level = MessageBanner::Level::Info;
    if (d.health.faults || d.stopReported)
        level = MessageBanner::Level::Error;
    else if (!problems.isEmpty())
        level = MessageBanner::Level::Warning;
    const QString now =
        problems.isEmpty() ? tr("values in range") : problems.join(QStringLiteral("; "));
    m_banner->setEntry(entryKey(id), level,
                       QStringLiteral("<b>%1</b> %2 <i>%3</i>")
                           .arg(tr("Drive %1: %2.").arg(id).arg(now).toHtmlEscaped(),
                                tr("Seen:").toHtmlEscaped(),
                                d.events.join(QStringLiteral("; ")).toHtmlEscaped()));
}

} // namespace lk::ui
