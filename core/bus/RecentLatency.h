#pragma once

#include <array>
#include <cstddef>

namespace lk::bus {

/// The latencies of the last few replies, and what they say about how soon a reply can come.
/// Used to tell a stale reply (the late answer to an earlier, timed-out identical request)
/// from the answer to the request just sent.
class RecentLatency {
public:
    static constexpr size_t kSize = 32;

    void add(double seconds) { m_samples[m_count++ % kSize] = seconds; }
    void clear() { m_count = 0; }

    /// How soon after a send its reply can arrive: never faster than its bytes cross the
    /// wire (`wireS`). A link without a real wire (the in-process simulator) shows it by
    /// answering faster than that: then 90 % of the typical (median) recent reply. The
    /// median, not the minimum, so that a few stale replies taken for fresh ones cannot lower
    /// the bar that keeps them out. 0 before any reply.
    double earliestReplyS(double wireS) const;

private:
    std::array<double, kSize> m_samples{};
    size_t m_count = 0;
};

} // namespace lk::bus
