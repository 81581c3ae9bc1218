#pragma once

#include <atomic>
#include <thread>
#include <vector>

namespace lk::e2e {

/// Busy loops on every core for a bounded time: the loaded laptop of a half-duplex test.
/// The threads stop at stop(), at destruction, or after `maxSeconds` whichever comes first,
/// so a test that fails half-way never leaves the machine spinning.
class CpuHog {
public:
    struct Options {
        double maxSeconds = 60;
        int threads = 0; ///< 0: one per core
        int burstMs = 0; ///< > 0: spin this long, then pause
        int pauseMs = 0; ///< the pause between bursts
    };
    explicit CpuHog(const Options &options);
    ~CpuHog(); ///< stop()
    CpuHog(const CpuHog &) = delete;
    CpuHog &operator=(const CpuHog &) = delete;

    void stop();
    int threadCount() const { return int(m_threads.size()); }
    /// Loop turns done so far by all threads (proof that they ran).
    unsigned long long turns() const { return m_turns.load(); }

private:
    std::atomic<bool> m_stop{false};
    std::atomic<unsigned long long> m_turns{0};
    std::atomic<unsigned long long> m_sink{0};
    std::vector<std::thread> m_threads;
};

} // namespace lk::e2e
