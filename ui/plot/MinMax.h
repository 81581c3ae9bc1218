#pragma once

#include <algorithm>
#include <limits>

namespace lk::ui {

/// The smallest and largest of a set of values; invalid while the set is empty.
struct MinMax {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();

    bool isValid() const { return min <= max; }
    void add(double value)
    {
        min = std::min(min, value);
        max = std::max(max, value);
    }
    void add(const MinMax &other)
    {
        min = std::min(min, other.min);
        max = std::max(max, other.max);
    }
};

} // namespace lk::ui
