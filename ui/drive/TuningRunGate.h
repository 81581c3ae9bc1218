#pragma once

#include <protocol/Series.h>
#include <safety/SoftLimits.h>
#include <tuning/FrequencySweepPlan.h>
#include <tuning/StepTestRunner.h>
#include <tuning/TuningEnd.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QPointer>
#include <QtCore/QString>

#include <optional>

class QWidget;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class TuningView;

/// The drive a frequency sweep or a gain search may run on, as the Tuning view has it.
struct TuningRunDrive {
    QPointer<bus::BusSession> session;
    int id = 0;
    std::optional<protocol::Series> series;
    QString model;
    double gearRatio = 1;
    safety::SoftLimits limits;
};

/// What a frequency sweep and a gain search check before they start, alike: a drive that can
/// be sent to, its gains read completely on this connection (the Tuning view's read), the soft
/// limits in force (the Control view's), and the user's word that the axis is free to turn that
/// far. The loop decides the angle window: the speed loop's runs turn the axis for as long as
/// they run, so they refuse one; the position loop's sine stays around where the drive is,
/// inside the window, so it needs one (both ends). Each refusal says why and that nothing was
/// sent.
class TuningRunGate {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::TuningRunGate)
public:
    /// The drive, or nullopt with `why` (a sentence that says nothing was sent).
    static std::optional<TuningRunDrive> check(const TuningView &host, tuning::SweepLoop loop,
                                               QString *why);
    /// check() for the speed loop.
    static std::optional<TuningRunDrive> check(const TuningView &host, QString *why)
    {
        return check(host, tuning::SweepLoop::Speed, why);
    }
    /// Whether the limits in force for the host's drive have an angle window (the position
    /// loop's response is offered then).
    static bool positionOffered(const TuningView &host);
    /// Whether both ends of an angle window are set: what a position loop's run needs.
    static bool hasAngleWindow(const safety::SoftLimits &limits)
    {
        return limits.minAngleDeg && limits.maxAngleDeg;
    }
    /// How far the axis turns: between `minDps` and `maxDps` for about `seconds`.
    static QString travelText(const TuningRunDrive &drive, double minDps, double maxDps,
                              double seconds);
    /// How far a position sine moves the axis: `amplitude` either side of where it is, at up to
    /// `peakDps`, inside the angle window, for about `seconds`.
    static QString positionTravelText(const TuningRunDrive &drive, double amplitudeDeg,
                                      double peakDps, double seconds);
    /// Asks whether the axis is free to turn as travelText() says; `key` names the question.
    static bool askFreeToTurn(QWidget *parent, const TuningRunDrive &drive, const QString &key,
                              const QString &what, const QString &travel);
    /// How a sweep that did not finish ended, and what the drive was left doing: from its
    /// typed outcome (tuning::TuningOutcome), never from the runner's English account.
    static QString failureText(tuning::StepTestFailure failure, const tuning::TuningOutcome &o,
                               int id);
    /// What the drive does after a sweep that finished: back at the speed read before it, or
    /// holding the angle it started at.
    static QString endedText(const tuning::TuningOutcome &o, int id);
};

} // namespace lk::ui
