#include "SoftLimitsFeed.h"

#include <bus/BusSession.h>

namespace lk::ui {

SoftLimitsFeed::SoftLimitsFeed(std::unique_ptr<DriveSettingsStore> store, bus::BusSession *session,
                               QObject *parent)
    : QObject(parent), m_store(std::move(store)), m_session(session)
{
    connect(session, &bus::BusSession::knownMotorsChanged, this, &SoftLimitsFeed::feedAll);
    feedAll();
}

void SoftLimitsFeed::feedAll()
{
    if (!m_session)
        return;
    const bus::KnownMotors motors = m_session->knownMotors();
    for (auto it = motors.cbegin(); it != motors.cend(); ++it) {
        const safety::SoftLimits defaults = safety::SoftLimits::defaults(it->series);
        const safety::SoftLimits limits =
            m_store->softLimits(driveKey(it.key(), *it), defaults).value_or(defaults);
        const auto was = m_fed.constFind(it.key());
        if (was != m_fed.cend() && *was == limits)
            continue;
        m_fed.insert(it.key(), limits);
        m_session->setSoftLimits(it.key(), limits);
    }
}

std::optional<safety::SoftLimits> SoftLimitsFeed::fed(int id) const
{
    const auto it = m_fed.constFind(id);
    return it == m_fed.cend() ? std::nullopt : std::optional(*it);
}

std::optional<safety::SoftLimits> SoftLimitsFeed::softLimits(const QString &driveKey,
                                                             const safety::SoftLimits &fallback,
                                                             QString *error)
{
    return m_store->softLimits(driveKey, fallback, error);
}

void SoftLimitsFeed::setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits)
{
    m_store->setSoftLimits(driveKey, limits);
    feedAll();
}

std::optional<int> SoftLimitsFeed::encoderBits(const QString &driveKey)
{
    return m_store->encoderBits(driveKey);
}

void SoftLimitsFeed::setEncoderBits(const QString &driveKey, int bits)
{
    m_store->setEncoderBits(driveKey, bits);
}

std::optional<double> SoftLimitsFeed::gearRatio(const QString &driveKey)
{
    return m_store->gearRatio(driveKey);
}

void SoftLimitsFeed::setGearRatio(const QString &driveKey, double ratio)
{
    m_store->setGearRatio(driveKey, ratio);
}

} // namespace lk::ui
