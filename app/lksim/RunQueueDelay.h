#pragma once

namespace lk::app {

/// How long the calling thread has waited for a CPU while runnable (Linux schedstat
/// run_delay): the lateness a loaded machine adds to a wake-up, which no clock read after the
/// wake-up can see. Open it on the thread it measures.
class RunQueueDelay {
public:
    RunQueueDelay();
    ~RunQueueDelay();
    RunQueueDelay(const RunQueueDelay &) = delete;
    RunQueueDelay &operator=(const RunQueueDelay &) = delete;

    /// The thread's total wait so far, in seconds; 0 where the kernel does not keep it.
    double seconds() const;

private:
    int m_fd = -1;
};

} // namespace lk::app
