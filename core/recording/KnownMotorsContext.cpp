#include "KnownMotorsContext.h"

namespace lk::recording {

ContextSnapshot contextOf(const bus::KnownMotors &motors)
{
    ContextSnapshot out;
    for (const bus::KnownMotor &m : motors)
        out.append(DriveContext{m.id, m.series, m.generation, m.identityChosen});
    return out;
}

RecordEvent contextRecord(qint64 timeNs, const bus::KnownMotors &motors)
{
    RecordEvent e;
    e.kind = RecordEvent::Kind::Context;
    e.timeNs = timeNs;
    e.context = contextOf(motors);
    return e;
}

} // namespace lk::recording
