#pragma once

#include "RunList.h"

#include <tuning/FrequencyRun.h>

namespace lk::ui {

using FrequencyRun = tuning::FrequencyRun;

/// The frequency sweeps of this session (RunList: numbered, overlaid).
class FrequencyRunList : public RunList<FrequencyRun> {
public:
    using RunList::RunList;
};

} // namespace lk::ui
