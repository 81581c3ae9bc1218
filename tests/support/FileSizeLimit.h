#pragma once

#include <csignal>

#include <sys/resource.h>

namespace lk::testsupport {

/// While it lives, no file this process writes grows past `bytes`: a disk that fills up
/// mid-file (a read-only folder would not stop the tests when they run as root). Writes past
/// the limit fail with EFBIG instead of raising SIGXFSZ.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) : m_oldHandler(std::signal(SIGXFSZ, SIG_IGN))
    {
        m_active = getrlimit(RLIMIT_FSIZE, &m_saved) == 0;
        rlimit small = m_saved;
        small.rlim_cur = bytes;
        m_active = m_active && setrlimit(RLIMIT_FSIZE, &small) == 0;
    }
    ~FileSizeLimit()
    {
        if (m_active)
            setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_oldHandler);
    }
    FileSizeLimit(const FileSizeLimit &) = delete;
    FileSizeLimit &operator=(const FileSizeLimit &) = delete;

    /// The limit is in force (setrlimit can refuse).
    bool isActive() const { return m_active; }

private:
    void (*m_oldHandler)(int);
    rlimit m_saved{};
    bool m_active = false;
};

} // namespace lk::testsupport
