#pragma once

#include "sim/SimDrive.h"

#include "SimTestUtil.h"

#include <QtTest/QTest>

#include <optional>

namespace lk::test {

/// Helpers for driving one SimDrive with typed requests (tests of the drive alone).
constexpr int kDriveId = 1;

inline sim::SimDrive makeDrive(protocol::Series s)
{
    return sim::SimDrive(kDriveId, sim::SimDriveModel::forSeries(s));
}

inline std::optional<protocol::Reply> send(sim::SimDrive &d, const protocol::BuildResult &r)
{
    return d.handle(req(r));
}

/// A data-less command that the drive must answer.
inline void plain(sim::SimDrive &d, protocol::Command c)
{
    QVERIFY(send(d, protocol::build::plain(c, kDriveId)).has_value());
}

/// The payload of the drive's answer to a data-less read (T must match the command).
template <typename T> T readBack(sim::SimDrive &d, protocol::Command c)
{
    return payloadOf<T>(d.handle(req(protocol::build::plain(c, kDriveId))));
}

inline double angleDeg(const sim::SimDrive &d)
{
    return static_cast<double>(d.multiTurnRaw()) * 0.01;
}

/// Runs the drive in steps of dt until pred() or the time is up; returns the simulated time.
template <typename Pred>
double runUntil(sim::SimDrive &d, double maxSeconds, Pred pred, double dt = 0.01)
{
    double t = 0;
    while (t < maxSeconds && !pred()) {
        d.advance(dt);
        t += dt;
    }
    return t;
}

} // namespace lk::test
