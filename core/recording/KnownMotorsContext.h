#pragma once

#include "RecordingFormat.h"

#include <bus/KnownMotor.h>

namespace lk::recording {

/// The decode context the session knows (BusSession::knownMotors), as a recording keeps it.
ContextSnapshot contextOf(const bus::KnownMotors &motors);

/// A Context record of `motors` at `timeNs`: append it to the recording's sink whenever
/// BusSession::knownMotorsChanged fires, so that a replay decodes as the session did.
RecordEvent contextRecord(qint64 timeNs, const bus::KnownMotors &motors);

} // namespace lk::recording
