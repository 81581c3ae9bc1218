#include "RecentLatency.h"

#include <algorithm>

namespace lk::bus {

double RecentLatency::earliestReplyS(double wireS) const
{
    const size_t n = std::min(m_count, kSize);
    if (n == 0)
        return 0;
    std::array<double, kSize> sorted = m_samples;
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.begin() + n);
    return std::min(wireS, 0.9 * sorted[n / 2]);
}

} // namespace lk::bus
