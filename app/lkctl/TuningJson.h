#pragma once

#include <tuning/FrequencyResponse.h>
#include <tuning/LoopGains.h>

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace lk::lkctl {

/// The JSON and text lkctl freq and lkctl tune print for gains and responses.
namespace TuningJson {
/// {"angle_kp":..,"angle_ki":..,..,"iq_ki":..} (read_pid's names; "*_kd" on V2.35) and
/// "accel_dps2".
QByteArray gains(const tuning::LoopGains &gains);
/// "speed Kp 50 Ki 40" (and "Kd 0" on V2.35).
QString speedGainsText(const tuning::LoopGains &gains);
/// [{"hz":..,"magnitude_db":..,"phase_deg":..,"quality":..,"samples":..},...]
QByteArray points(const tuning::FrequencyResponse &response);
/// [{"hz":..,"reason":"above_resolution"|"too_few_samples"|"no_input"},...]
QByteArray dropped(const tuning::FrequencyResponse &response);
const char *droppedWord(tuning::DroppedReason reason);
} // namespace TuningJson

} // namespace lk::lkctl
