#pragma once

#include "RunList.h"

#include <tuning/FrequencyResponse.h>
#include <tuning/FrequencySweepPlan.h>
#include <tuning/LoopGains.h>

#include <QtCore/QDateTime>
#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// One frequency sweep kept in the session: what was asked, on which drive, with which gains,
/// and the response measured.
struct FrequencyRun {
    int number = 0;  ///< "Run 3"
    QString label;   ///< the user's name for it; may be empty
    QDateTime ranAt; ///< when the sweep started, UTC
    int driveId = 0; ///< 1..32
    QString series;  ///< "MS", "MF", "MG" or "MH"; empty if unknown
    QString model;   ///< read_model's motor name; empty if unknown
    tuning::FrequencySweepSpec spec;
    std::optional<tuning::LoopGains> gains; ///< as the sweep read them
    tuning::FrequencyResponse response;
};

/// The frequency sweeps of this session (RunList: numbered, overlaid).
class FrequencyRunList : public RunList<FrequencyRun> {
public:
    using RunList::RunList;
};

} // namespace lk::ui
