#pragma once

#include <protocol/Request.h>

#include <QtTest/QTest>

namespace lk::test {

/// A request from a builder that must succeed (test input, not code under test).
inline protocol::Request req(const protocol::BuildResult &r)
{
    if (!r.ok())
        qFatal("test request did not build: %s", qPrintable(r.error.message()));
    return *r.request;
}

} // namespace lk::test
