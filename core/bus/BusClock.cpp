#include "BusClock.h"

#include <QtCore/QElapsedTimer>

namespace lk::bus {

namespace {
class SteadyBusClock final : public BusClock {
public:
    SteadyBusClock() { m_elapsed.start(); }
    qint64 nowNs() const override { return m_elapsed.nsecsElapsed(); }

private:
    QElapsedTimer m_elapsed;
};
} // namespace

std::shared_ptr<BusClock> makeSteadyBusClock()
{
    return std::make_shared<SteadyBusClock>();
}

} // namespace lk::bus
