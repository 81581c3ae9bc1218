#include "GainSearchViewOutcome.h"

#include <panels/Format.h>
#include <text/VerdictText.h>

#include <QtCore/QStringList>

namespace lk::ui {

using tuning::DriveLeft;
using tuning::SearchEnd;

QString GainSearchViewOutcome::endText(const tuning::GainSearchResult &r)
{
    const int id = r.spec.id;
    const int tried = int(r.candidates.size());
    const QString seconds = Format::number(r.seconds, 0);
    switch (r.outcome.end) {
    case SearchEnd::Finished:
    case SearchEnd::Unstable: {
        QString text = r.best ? tr("%n candidate(s) tried in %1 s; the best is in bold, Write to "
                                   "RAM tries it. Nothing else was kept.",
                                   nullptr, tried)
                                    .arg(seconds)
                              : tr("%n candidate(s) tried in %1 s; none stayed within the "
                                   "bounds.",
                                   nullptr, tried)
                                    .arg(seconds);
        if (r.outcome.end == SearchEnd::Unstable)
            text += QLatin1Char(' ') + tr("The search stopped at the first unstable candidate.");
        return text;
    }
    case SearchEnd::AbortedByUser:
        return tr("Stopped.");
    case SearchEnd::EmergencyStop:
        return tr("Stopped by an emergency stop.");
    case SearchEnd::Refused:
        return r.refusal.verdict.allowed()
                   ? tr("Refused by a soft limit.")
                   : tr("Refused: %1.").arg(text::VerdictText::stepRefusal(r.refusal));
    case SearchEnd::BadSpec:
        return tr("It cannot run as set.");
    case SearchEnd::FailedToRead:
        return tr("The gains of drive %1 could not be read.").arg(id);
    case SearchEnd::DriveSilent:
        return tr("Drive %1 did not answer: it stopped.").arg(id);
    case SearchEnd::LinkLost:
        return tr("The link went down: it stopped.");
    case SearchEnd::FailedToRestore:
        return tr("The gains read could not be written back at the end: it stopped.");
    }
    return {};
}

QString GainSearchViewOutcome::driveText(const tuning::TuningOutcome &o, int id)
{
    switch (o.drive) {
    case DriveLeft::Untouched:
        return tr("Nothing was sent.");
    case DriveLeft::NoStepSent:
        return tr("No step was sent.");
    case DriveLeft::Off:
        return tr("Motor Off went to drive %1 and it acknowledged.").arg(id);
    case DriveLeft::MayBeMoving:
        return tr("Drive %1 did not acknowledge Motor Off: it may still be moving.").arg(id);
    case DriveLeft::HoldsZero:
        return tr("Drive %1 holds 0 dps, its motor stays on.").arg(id);
    case DriveLeft::BackAtSpeed:
        return tr("Drive %1 is back at %2 dps, the speed it had, and keeps turning until "
                  "stopped.")
            .arg(id)
            .arg(Format::number(o.speedDps, 0));
    case DriveLeft::HoldsAngle:
        return tr("Drive %1 holds %2 deg, the angle it started at, its motor stays on.")
            .arg(id)
            .arg(Format::number(o.angleDeg, 2));
    }
    return {};
}

QString GainSearchViewOutcome::gainsText(const tuning::TuningOutcome &o)
{
    if (o.drive == DriveLeft::Untouched)
        return {};
    return o.gainsRestored ? tr("The gains read are back in RAM.")
                           : tr("The gains read before could NOT be written back: read the "
                                "drive and check them.");
}

QString GainSearchViewOutcome::text(const tuning::GainSearchResult &r)
{
    return QStringList{endText(r), driveText(r.outcome, r.spec.id), gainsText(r.outcome)}
        .join(QLatin1Char(' '))
        .simplified();
}

} // namespace lk::ui
