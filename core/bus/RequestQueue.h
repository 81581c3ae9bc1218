#pragma once

#include "BusRequest.h"

#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace lk::bus {

/// Three FIFO lanes, Emergency > Operator > Background. Retries go back to the head of their
/// own lane, so an emergency stop still overtakes them.
class RequestQueue {
public:
    void push(PendingRequest p);
    void pushFront(PendingRequest p);
    /// Into its lane ahead of the first request `ahead` selects; at the back when none does.
    void pushBefore(PendingRequest p, const std::function<bool(const PendingRequest &)> &ahead);
    /// The first request of the highest non-empty lane.
    std::optional<PendingRequest> takeNext();
    /// Remove and return every request `which` selects, in lane order.
    std::vector<PendingRequest> takeIf(const std::function<bool(const PendingRequest &)> &which);
    int size() const;
    bool isEmpty() const { return size() == 0; }

private:
    std::deque<PendingRequest> &lane(const PendingRequest &p);

    std::array<std::deque<PendingRequest>, 3> m_lanes; ///< by Priority
};

} // namespace lk::bus
