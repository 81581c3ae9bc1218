#include "EncoderResolutions.h"

#include "DriveSettingsStore.h"

#include <bus/BusSession.h>

#include <algorithm>
#include <map>

namespace lk::ui {

EncoderResolutions::EncoderResolutions(QObject *parent)
    : QObject(parent), m_ownStore(std::make_unique<MemoryDriveStore>()), m_store(m_ownStore.get())
{
}

EncoderResolutions::~EncoderResolutions() = default;

void EncoderResolutions::setSession(bus::BusSession *session)
{
    if (session == m_session)
        return;
    disconnect(m_telemetry);
    m_session = session;
    m_byKey.clear();
    m_described.clear();
    if (session)
        m_telemetry = connect(session, &bus::BusSession::telemetryReceived, this,
                              qOverload<const bus::TelemetryBatch &>(&EncoderResolutions::observe));
}

void EncoderResolutions::setSettingsStore(DriveSettingsStore *store)
{
    m_store = store ? store : m_ownStore.get();
    m_byKey.clear(); // user choices come from the new store
}

motor::EncoderResolution &EncoderResolutions::entry(int id, const bus::KnownMotor &motor)
{
    const QString key = DriveSettingsStore::driveKey(id, motor);
    auto it = m_byKey.find(key);
    if (it == m_byKey.end()) {
        const QString name = motor.model ? motor.model->motorName : QString();
        auto r = motor::EncoderResolution::fromModel(motor::ModelNameInfo::parse(name),
                                                     motor.series, motor.generation);
        if (const auto bits = m_store->encoderBits(key))
            r.setUserBits(*bits);
        it = m_byKey.insert(key, r);
    }
    return *it;
}

motor::EncoderResolution EncoderResolutions::of(int id, const bus::KnownMotor &motor)
{
    m_described.insert(id, motor);
    return entry(id, motor);
}

bus::KnownMotor EncoderResolutions::motorOf(int id) const
{
    bus::KnownMotor motor;
    if (m_session && m_session->knownMotors().contains(id))
        motor = m_session->knownMotors().value(id);
    else
        motor = m_described.value(id);
    motor.id = id;
    return motor;
}

void EncoderResolutions::setUserBits(int id, const bus::KnownMotor &motor, int bits)
{
    motor::EncoderResolution &r = entry(id, motor);
    if (!r.setUserBits(bits))
        return;
    m_store->setEncoderBits(DriveSettingsStore::driveKey(id, motor), bits);
    emit changed(id);
}

void EncoderResolutions::observe(const bus::TelemetryBatch &batch)
{
    if (batch.isEmpty())
        return;
    // Only the largest value of each drive can raise its resolution: one lookup per drive and
    // batch, not one per sample (a settings key is built for each lookup).
    std::map<int, int> largest;
    for (const bus::TelemetrySample &s : batch) {
        if (s.has(bus::TelemetryField::Encoder)) {
            const auto [it, inserted] = largest.try_emplace(s.id, s.encoder);
            if (!inserted)
                it->second = std::max(it->second, s.encoder);
        }
    }
    for (const auto &[id, encoder] : largest)
        observe(id, motorOf(id), encoder);
}

void EncoderResolutions::observe(int id, const bus::KnownMotor &motor, int encoder)
{
    if (entry(id, motor).observe(encoder))
        emit changed(id);
}

QString EncoderResolutions::readoutText(int value, const motor::EncoderResolution &resolution)
{
    using Source = motor::EncoderResolution::Source;
    const int bits = resolution.bits();
    QString how;
    switch (resolution.source()) {
    case Source::Name:
        how = tr("%1-bit, from the model name").arg(bits);
        break;
    case Source::Generation:
        how = tr("%1-bit, protocol V2.35").arg(bits);
        break;
    case Source::SeriesDefault:
        how = tr("%1-bit, series default").arg(bits);
        break;
    case Source::Guess:
        how = tr("%1-bit, a guess").arg(bits);
        break;
    case Source::Data:
        how = tr("%1-bit, from data").arg(bits);
        break;
    case Source::User:
        how = tr("%1-bit, your setting").arg(bits);
        break;
    }
    return tr("%1 of %2 (%3)").arg(value).arg(resolution.countsPerTurn()).arg(how);
}

QString EncoderResolutions::sourceText(const motor::EncoderResolution &resolution,
                                       const QString &motorName,
                                       std::optional<protocol::Series> series)
{
    using Source = motor::EncoderResolution::Source;
    QString text;
    switch (resolution.source()) {
    case Source::Name:
        text = tr("from the model name \"%1\"").arg(motorName);
        break;
    case Source::Generation:
        text = tr("what protocol V2.35 documents for %1 drives (a real MS4015 on firmware 2.35 "
                  "reports 16 bits)")
                   .arg(series ? protocol::seriesName(*series) : QString());
        break;
    case Source::SeriesDefault:
        text = series ? tr("the %1 series default").arg(protocol::seriesName(*series))
                      : tr("a guess: the model does not say");
        break;
    case Source::Guess:
        text = tr("a guess: the model does not say");
        break;
    case Source::Data:
        text = tr("from data: the drive reported %1, beyond the range assumed before")
                   .arg(resolution.largestSeen().value_or(0));
        break;
    case Source::User:
        text = tr("your setting for this drive");
        break;
    }
    if (resolution.contradictedByData())
        text += QLatin1String("; ") + tr("but the drive reported %1, beyond this range")
                                          .arg(resolution.largestSeen().value_or(0));
    return text;
}

} // namespace lk::ui
