#include "AngleCheck.h"

#include <cmath>

namespace lk::ui {

AngleCheck AngleCheck::classify(double beforeDeg, double afterDeg, double toleranceDeg)
{
    AngleCheck c;
    c.beforeDeg = beforeDeg;
    c.afterDeg = afterDeg;
    const bool zeroAfter = std::fabs(afterDeg) <= toleranceDeg;
    if (zeroAfter)
        c.outcome = std::fabs(beforeDeg) <= toleranceDeg ? Outcome::AlreadyZero : Outcome::Cleared;
    else if (std::fabs(afterDeg - beforeDeg) <= toleranceDeg)
        c.outcome = Outcome::Unchanged;
    else
        c.outcome = Outcome::ChangedNotZero;
    return c;
}

} // namespace lk::ui
