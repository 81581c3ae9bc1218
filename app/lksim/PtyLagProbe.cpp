#include "PtyLagProbe.h"

#include <algorithm>
#include <limits>

namespace lk::app {

namespace {
/// A canary held this long shows a kernel worker waiting; unloaded, one comes through in
/// tens of microseconds.
constexpr double kHoldShownS = 0.0003;
/// A canary that came through this recently still tells about bytes read now: after a wait
/// the worker hands over the queued bytes of both ptys one after the other, and lksim may
/// read them in two wake-ups.
constexpr double kRecentS = 0.002;
} // namespace

PtyLagProbe::PtyLagProbe(double periodS) : m_periodS(periodS) {}

bool PtyLagProbe::open()
{
    return m_pty.open();
}

bool PtyLagProbe::service(double nowS)
{
    if (!m_pty.readAvailable().isEmpty())
        noteArrived(nowS);
    if (untilNextSendS(nowS) > 0)
        return true;
    if (!m_pty.writeToSlave(QByteArray(1, '\x55')))
        return false;
    noteSent(nowS);
    return true;
}

double PtyLagProbe::untilNextSendS(double nowS) const
{
    if (m_sentAt >= 0)
        return std::numeric_limits<double>::max();
    return std::max(0.0, m_lastSentAt + m_periodS - nowS);
}

void PtyLagProbe::noteSent(double nowS)
{
    m_sentAt = m_lastSentAt = nowS;
}

void PtyLagProbe::noteArrived(double nowS)
{
    if (m_sentAt < 0)
        return;
    m_lastHoldS = nowS - m_sentAt;
    m_arrivedAt = nowS;
    m_sentAt = -1;
    ++m_arrivals;
}

double PtyLagProbe::heldS(double nowS) const
{
    double held = 0;
    if (m_sentAt >= 0)
        held = nowS - m_sentAt;
    if (nowS - m_arrivedAt <= kRecentS)
        held = std::max(held, m_lastHoldS);
    return held >= kHoldShownS ? held + m_periodS : 0;
}

} // namespace lk::app
