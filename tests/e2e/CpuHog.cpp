#include "CpuHog.h"

#include <algorithm>
#include <chrono>

namespace lk::e2e {

CpuHog::CpuHog(const Options &o)
{
    using Clock = std::chrono::steady_clock;
    const int n =
        o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(o.maxSeconds));
    for (int i = 0; i < n; ++i) {
        m_threads.emplace_back([this, deadline, o] {
            unsigned long long local = 0;
            auto burstEnd = Clock::now() + std::chrono::milliseconds(o.burstMs);
            while (!m_stop.load(std::memory_order_relaxed)) {
                if (o.burstMs > 0 && Clock::now() >= burstEnd) {
                    std::this_thread::sleep_for(std::chrono::milliseconds(o.pauseMs));
                    burstEnd = Clock::now() + std::chrono::milliseconds(o.burstMs);
                }
                // Pure computation; the clock is read only now and then.
                for (int k = 0; k < 100000; ++k)
                    local = local * 6364136223846793005ULL + 1442695040888963407ULL;
                m_turns.fetch_add(1, std::memory_order_relaxed);
                m_sink.store(local, std::memory_order_relaxed); // the loop is not optimised away
                if (std::chrono::steady_clock::now() >= deadline)
                    break;
            }
        });
    }
}

CpuHog::~CpuHog()
{
    stop();
}

void CpuHog::stop()
{
    m_stop.store(true);
    for (std::thread &t : m_threads) {
        if (t.joinable())
            t.join();
    }
}

} // namespace lk::e2e
