#include "RequestResult.h"

namespace lk::bus {

const char *requestStatusName(RequestStatus s)
{
    switch (s) {
    case RequestStatus::Ok:
        return "ok";
    case RequestStatus::Timeout:
        return "timeout";
    case RequestStatus::Disconnected:
        return "disconnected";
    case RequestStatus::Cancelled:
        return "cancelled";
    case RequestStatus::Error:
        return "error";
    }
    return "?";
}

} // namespace lk::bus
