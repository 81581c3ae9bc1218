#include "RequestQueue.h"

#include <algorithm>

namespace lk::bus {

std::deque<PendingRequest> &RequestQueue::lane(const PendingRequest &p)
{
    return m_lanes[static_cast<size_t>(p.req.priority)];
}

void RequestQueue::push(PendingRequest p)
{
    lane(p).push_back(std::move(p));
}

void RequestQueue::pushFront(PendingRequest p)
{
    lane(p).push_front(std::move(p));
}

void RequestQueue::pushBefore(PendingRequest p,
                              const std::function<bool(const PendingRequest &)> &ahead)
{
    std::deque<PendingRequest> &q = lane(p);
    q.insert(std::find_if(q.begin(), q.end(), ahead), std::move(p));
}

std::optional<PendingRequest> RequestQueue::takeNext()
{
    for (auto &q : m_lanes) {
        if (!q.empty()) {
            PendingRequest p = std::move(q.front());
            q.pop_front();
            return p;
        }
    }
    return std::nullopt;
}

std::vector<PendingRequest>
RequestQueue::takeIf(const std::function<bool(const PendingRequest &)> &which)
{
    std::vector<PendingRequest> out;
    for (auto &q : m_lanes) {
        for (auto it = q.begin(); it != q.end();) {
            if (which(*it)) {
                out.push_back(std::move(*it));
                it = q.erase(it);
            } else {
                ++it;
            }
        }
    }
    return out;
}

int RequestQueue::size() const
{
    int n = 0;
    for (const auto &q : m_lanes)
        n += static_cast<int>(q.size());
    return n;
}

} // namespace lk::bus
