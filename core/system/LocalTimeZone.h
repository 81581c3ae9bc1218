#pragma once

namespace lk::system {

/// Has the C library read the local time zone once per process instead of at every conversion.
///
/// With TZ unset, glibc stats /etc/localtime again at every conversion to local time, to see
/// whether the zone changed. Qt converts at every QDateTime::currentDateTime(), and Qt's CAN
/// plugins stamp every frame that way (virtualcan does it twice a frame): on a CAN bus at
/// its full rate that is some 6000 system calls a second on the bus thread. Setting TZ to
/// ":/etc/localtime" names the same zone, and glibc then reads it once. The price: a change of
/// the machine's time zone is seen after a restart, as by many programs.
class LocalTimeZone {
public:
    /// Sets TZ when it is unset and /etc/localtime exists; anything the user set is kept.
    /// Call first in main(), before any thread starts (setenv is not thread-safe).
    static void readOnce();
};

} // namespace lk::system
