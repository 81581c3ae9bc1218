#pragma once

#include "E2eUtil.h"

#include <algorithm>

namespace lk::e2e {

/// simArgs() with `motors` instead of simMotors() and lksim's frame log on (--verbose), for
/// tests that count what reached the bus.
inline QStringList loggedSimArgs(const QString &link, const QString &motors,
                                 const QStringList &extra = {})
{
    QStringList args = simArgs(link, QStringList{QStringLiteral("--verbose")} + extra);
    args[args.indexOf(QStringLiteral("--motors")) + 1] = motors;
    return args;
}

/// How many of the frames lksim received start with `start` ("3E 19 03": write_zero_rom to 3).
inline qsizetype framesStartingWith(LksimProcess &sim, const QByteArray &start)
{
    const QList<QByteArray> frames = sim.receivedFrames();
    return std::count_if(frames.cbegin(), frames.cend(),
                         [&start](const QByteArray &f) { return f.startsWith(start); });
}

} // namespace lk::e2e
