#include "RunQueueDelay.h"

#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>

namespace lk::app {

RunQueueDelay::RunQueueDelay() : m_fd(::open("/proc/thread-self/schedstat", O_RDONLY | O_CLOEXEC))
{
}

RunQueueDelay::~RunQueueDelay()
{
    if (m_fd >= 0)
        ::close(m_fd);
}

double RunQueueDelay::seconds() const
{
    if (m_fd < 0)
        return 0;
    // "<ns on a CPU> <ns waiting on a run queue> <timeslices>"; pread: the kernel renders the
    // file anew at offset 0, so one open file serves every reading.
    char text[96];
    const ssize_t n = ::pread(m_fd, text, sizeof text - 1, 0);
    if (n <= 0)
        return 0;
    text[n] = '\0';
    char *end = nullptr;
    std::strtoull(text, &end, 10);
    const unsigned long long waitNs = std::strtoull(end, nullptr, 10);
    return static_cast<double>(waitNs) * 1e-9;
}

} // namespace lk::app
