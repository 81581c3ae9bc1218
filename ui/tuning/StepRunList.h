#pragma once

#include "RunList.h"

#include <tuning/StepRun.h>

namespace lk::ui {

/// The step-test runs of this session (RunList: numbered, overlaid, loaded runs named by
/// their file).
class StepRunList : public RunList<tuning::StepRun> {
public:
    using RunList::RunList;
};

} // namespace lk::ui
