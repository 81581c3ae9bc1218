#include "TuningRunGate.h"

#include "ConfirmDialog.h"
#include "TuningView.h"

#include <bus/BusSession.h>
#include <motor/ModelNameInfo.h>
#include <panels/Format.h>
#include <tuning/StepTestPanel.h>

#include <cmath>

namespace lk::ui {

std::optional<TuningRunDrive> TuningRunGate::check(const TuningView &host, tuning::SweepLoop loop,
                                                   QString *why)
{
    const auto refuse = [why](const QString &text) {
        if (why)
            *why = text;
        return std::nullopt;
    };
    if (!host.canSendToDrive())
        return refuse(tr("Nothing was sent: connect and select a drive first."));
    // Nothing runs on gains this connection did not read: they are what an abort puts back.
    if (!host.readComplete())
        return refuse(tr("Nothing was sent: the gains of drive %1 have not been read on this "
                         "connection. Read from drive first.")
                          .arg(host.driveId()));
    if (host.isBusy() || host.stepTest()->isRunning())
        return refuse(tr("Nothing was sent: a step test, read or write of drive %1 is in "
                         "progress.")
                          .arg(host.driveId()));
    QString limitWhy;
    const StepTestSources &sources = host.stepTest()->sources();
    const std::optional<safety::SoftLimits> limits =
        sources.limits ? sources.limits(&limitWhy) : std::nullopt;
    if (!limits)
        return refuse(limitWhy.isEmpty() ? tr("Nothing was sent: no soft limits are in force.")
                                         : limitWhy);
    if (loop == tuning::SweepLoop::Position && !hasAngleWindow(*limits))
        return refuse(tr("Refused: the position loop's response needs an angle range for drive "
                         "%1 (Control view, both ends): its sine stays inside it. Nothing was "
                         "sent.")
                          .arg(host.driveId()));
    if (loop == tuning::SweepLoop::Speed && (limits->minAngleDeg || limits->maxAngleDeg))
        return refuse(tr("Refused: an angle range is set for drive %1 (Control view), and this "
                         "turns the axis for as long as it runs, past any range. Nothing was "
                         "sent.")
                          .arg(host.driveId()));
    TuningRunDrive d;
    d.session = host.session();
    d.id = host.driveId();
    d.series = host.series();
    d.limits = *limits;
    if (const auto &m = host.motor().model) {
        d.model = m->motorName;
        d.gearRatio = motor::ModelNameInfo::parse(m->motorName).gearRatio;
    }
    return d;
}

QString TuningRunGate::travelText(const TuningRunDrive &drive, double minDps, double maxDps,
                                  double seconds)
{
    // The speed stays between the two: the rotor turns at most the larger one's worth.
    const double rotorDeg = std::max(std::abs(minDps), std::abs(maxDps)) * seconds;
    const double outputTurns = rotorDeg / 360.0 / std::max(drive.gearRatio, 1e-9);
    return tr("Drive %1 turns at %2 to %3 dps (rotor) for about %4 s: up to %5 rotor turns, "
              "%6 turns of the output. Speed limit %7 dps.")
        .arg(drive.id)
        .arg(Format::number(minDps, 0), Format::number(maxDps, 0), Format::number(seconds, 1),
             Format::number(rotorDeg / 360.0, 1), Format::number(outputTurns, 1),
             Format::number(drive.limits.maxSpeedDps, 0));
}

bool TuningRunGate::positionOffered(const TuningView &host)
{
    const StepTestSources &sources = host.stepTest()->sources();
    const std::optional<safety::SoftLimits> limits =
        sources.limits ? sources.limits(nullptr) : std::nullopt;
    return limits && hasAngleWindow(*limits);
}

QString TuningRunGate::positionTravelText(const TuningRunDrive &drive, double amplitudeDeg,
                                          double peakDps, double seconds)
{
    return tr("Drive %1 swings up to %2\u00b0 (rotor) either side of where it is, at up to %3 dps, "
              "for about %4 s, inside the angle range %5\u00b0 to %6\u00b0. Speed limit %7 dps.")
        .arg(drive.id)
        .arg(Format::number(amplitudeDeg, 1), Format::number(peakDps, 0),
             Format::number(seconds, 1), Format::number(drive.limits.minAngleDeg.value_or(0), 1),
             Format::number(drive.limits.maxAngleDeg.value_or(0), 1),
             Format::number(drive.limits.maxSpeedDps, 0));
}

bool TuningRunGate::askFreeToTurn(QWidget *parent, const TuningRunDrive &drive, const QString &key,
                                  const QString &what, const QString &travel)
{
    ConfirmRequest q;
    q.key = key;
    q.title = what;
    q.question = tr("Is the axis of drive %1 free to turn?").arg(drive.id);
    q.reason = travel + QLatin1Char(' ') +
               tr("The gains read are written back to RAM at the end; Esc stops the motor at "
                  "once.");
    q.acceptText = tr("Start");
    return ConfirmDialog::ask(parent, q);
}

QString TuningRunGate::failureText(tuning::StepTestFailure failure, const tuning::TuningOutcome &o,
                                   int id)
{
    using F = tuning::StepTestFailure;
    using tuning::DriveLeft;
    QString how;
    switch (failure) {
    case F::None:
        return {};
    case F::BadSpec:
        how = tr("It cannot run as set.");
        break;
    case F::Refused:
        how = tr("Refused by a soft limit.");
        break;
    case F::Silent:
        how = tr("Drive %1 did not answer: it stopped.").arg(id);
        break;
    case F::Disconnected:
        how = tr("The link went down: it stopped.");
        break;
    case F::Aborted:
        how = tr("Stopped.");
        break;
    }
    if (o.drive == DriveLeft::Untouched)
        return how + QLatin1Char(' ') + tr("Nothing was sent.");
    QString off;
    switch (o.drive) {
    case DriveLeft::NoStepSent: // the acceleration limit was lifted and put back
        off = tr("No step was sent.");
        break;
    case DriveLeft::Off:
        off = tr("Motor Off went to drive %1 and it acknowledged.").arg(id);
        break;
    case DriveLeft::MayBeMoving:
        off = tr("Drive %1 did not acknowledge Motor Off: it may still be moving.").arg(id);
        break;
    default:
        break;
    }
    const QString gains = o.gainsRestored ? tr("The gains read before are back in RAM.")
                                          : tr("The gains read before could NOT be written "
                                               "back: read the drive and check them.");
    return QStringList{how, off, gains}.join(QLatin1Char(' ')).simplified();
}

QString TuningRunGate::endedText(const tuning::TuningOutcome &o, int id)
{
    using tuning::DriveLeft;
    switch (o.drive) {
    case DriveLeft::HoldsZero: // 0 dps holds with the motor on
        return tr("The gains read are back in RAM; drive %1 holds 0 dps, its motor stays on.")
            .arg(id);
    case DriveLeft::HoldsAngle:
        return tr("The gains read are back in RAM; drive %1 holds the angle it started at, its "
                  "motor stays on.")
            .arg(id);
    case DriveLeft::BackAtSpeed:
        return tr("The gains read are back in RAM; drive %1 is back at the speed it had and keeps "
                  "turning until stopped.")
            .arg(id);
    default:
        return tr("The gains read are back in RAM.");
    }
}

} // namespace lk::ui
