#include "TuningEnd.h"

#include "GainKeeper.h"

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionPlanner.h>

#include <QtCore/QTimer>

namespace lk::tuning {

void TuningEnd::readFirst(GainKeeper &keeper, int id, const QString &specError, QObject *context,
                          std::function<void(StepTestFailure, const QString &)> done)
{
    if (!specError.isEmpty()) {
        QTimer::singleShot(0, context, [done, specError] {
            done(StepTestFailure::BadSpec, specError + QStringLiteral("; nothing was sent"));
        });
        return;
    }
    keeper.read(id, [done](bool ok, const QString &why) {
        if (ok)
            done(StepTestFailure::None, QString());
        else
            done(StepTestFailure::Silent,
                 QStringLiteral("the gains could not be read (%1); nothing was sent").arg(why));
    });
}

QString HaltOutcome::words() const
{
    const QString off = offAcknowledged ? QStringLiteral("drive %1 is off").arg(id)
                                        : QStringLiteral("drive %1 did not acknowledge motor off: "
                                                         "it may still be moving")
                                              .arg(id);
    return QStringLiteral("%1; %2").arg(
        off, gainsRestored ? QStringLiteral("the gains and acceleration read before are back in "
                                            "RAM")
                           : QStringLiteral("the gains and acceleration read before could not be "
                                            "written back (%1)")
                                 .arg(restoreError));
}

void TuningEnd::haltAndRestore(bus::BusSession &session, GainKeeper &keeper, int id,
                               QObject *context, std::function<void(const QString &)> done)
{
    halt(session, keeper, id, context, [done](const HaltOutcome &h) { done(h.words()); });
}

void TuningEnd::halt(bus::BusSession &session, GainKeeper &keeper, int id, QObject *context,
                     std::function<void(const HaltOutcome &)> done)
{
    session.stopSetpointStream();
    session.emergencyStop({id}, protocol::Command::MotorOff, context,
                          [&keeper, id, done](const QVector<int> &acknowledged,
                                              const QVector<int> &, const QVector<int> &) {
                              HaltOutcome h;
                              h.id = id;
                              h.offAcknowledged = acknowledged.contains(id);
                              keeper.restore([h, done](bool ok, const QString &why) mutable {
                                  h.gainsRestored = ok;
                                  h.restoreError = why;
                                  done(h);
                              });
                          });
}

void TuningEnd::returnToSpeed(bus::BusSession &session, int id, double dps,
                              const safety::SoftLimits &limits, QObject *context,
                              std::function<void(bool, const QString &)> done)
{
    const protocol::BuildResult built = protocol::build::speed(id, dps);
    const safety::MotionPlan motion =
        built.ok() ? safety::MotionPlanner::plan(*built.request, session.series(id), limits, {})
                   : safety::MotionPlan{};
    if (!motion.allowed()) {
        QTimer::singleShot(0, context, [done, dps] {
            done(false, QStringLiteral("the speed read at the start (%1 dps) is beyond the "
                                       "limits")
                            .arg(dps));
        });
        return;
    }
    session.send(*motion.request, context, [id, dps, done](const bus::RequestResult &r) {
        if (!r.ok() && r.attempts == 0) { // refused before the wire: say why, not "no answer"
            done(false, QStringLiteral("the speed back to %1 dps was not sent to drive %2: %3")
                            .arg(dps)
                            .arg(id)
                            .arg(r.reason));
            return;
        }
        if (!r.ok()) {
            done(false, QStringLiteral("drive %1 did not answer the speed back to %2 dps")
                            .arg(id)
                            .arg(dps));
            return;
        }
        done(true, dps == 0 ? QStringLiteral("drive %1 holds 0 dps (the motor stays on)").arg(id)
                            : QStringLiteral("drive %1 is back at %2 dps, the speed read at the "
                                             "start; stop it with motor stop or off")
                                  .arg(id)
                                  .arg(dps));
    });
}

} // namespace lk::tuning
