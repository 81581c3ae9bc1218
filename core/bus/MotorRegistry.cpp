#include "MotorRegistry.h"

#include <motor/ModelNameInfo.h>
#include <protocol/Checksum.h>
#include <protocol/Command.h>

#include <QtCore/QCoreApplication>

#include <algorithm>

namespace lk::bus {

namespace {
bool validId(int id)
{
    return id >= protocol::kMinId && id <= protocol::kMaxId;
}
} // namespace

std::optional<protocol::Series> MotorRegistry::series(int id) const
{
    const auto it = m_motors.constFind(id);
    return it == m_motors.cend() ? std::nullopt : it->series;
}

protocol::DecodeContext MotorRegistry::decodeContext(int id) const
{
    protocol::DecodeContext c;
    c.link = m_link;
    const auto it = m_motors.constFind(id);
    if (it != m_motors.cend()) {
        c.series = it->series.value_or(protocol::Series::MF);
        c.generation = it->generation;
    }
    return c;
}

StopTargets MotorRegistry::emergencyTargets(const QVector<int> &ids) const
{
    QVector<int> urgent = ids;
    for (int id : m_moving)
        urgent.append(id);
    QList<int> known = m_motors.keys();
    for (int id : m_answered)
        known.append(id);
    return StopTargets::of(urgent, known);
}

std::optional<QString> MotorRegistry::unavailableReason(const protocol::Request &request) const
{
    // Nothing a drive's generation lacks is sent to it (docs/V2.35.md section 3): it would stay
    // silent and the timeout would blame the wiring.
    const auto it = m_motors.constFind(request.id);
    if (m_link == protocol::Link::Can) {
        // On CAN the link decides as much as the generation (docs/CAN.md section 3); a drive
        // of unknown generation is left to the codec, which refuses what the old one lacks.
        if (it == m_motors.cend() || !it->generationKnown() ||
            protocol::CommandTable::availableOn(request.command, decodeContext(request.id)))
            return std::nullopt;
        return QCoreApplication::translate("lk::bus::MotorRegistry",
                                           "drive %1 speaks %2, which has no %3; nothing was sent")
            .arg(request.id)
            .arg(protocol::dialectName(decodeContext(request.id)))
            .arg(protocol::CommandTable::name(request.command));
    }
    if (it == m_motors.cend() || !it->model ||
        protocol::CommandTable::availableOn(request.command, it->generation))
        return std::nullopt;
    const char *text =
        it->generation == protocol::Generation::V2_35
            ? QT_TRANSLATE_NOOP("lk::bus::MotorRegistry",
                                "drive %1 runs firmware 2.35 or later (protocol V2.35), which "
                                "has no %2; nothing was sent")
            : QT_TRANSLATE_NOOP("lk::bus::MotorRegistry",
                                "drive %1 speaks protocol V2.3, which has no %2 (firmware 2.35 "
                                "added it); nothing was sent");
    return QCoreApplication::translate("lk::bus::MotorRegistry", text)
        .arg(request.id)
        .arg(protocol::CommandTable::name(request.command));
}

bool MotorRegistry::noteSeen(int id)
{
    if (!validId(id))
        return false;
    m_answered.insert(id);
    if (m_motors.contains(id))
        return false;
    KnownMotor m;
    m.id = id;
    m_motors.insert(id, m);
    return true;
}

void MotorRegistry::noteMotion(int id, bool moving)
{
    if (!validId(id))
        return;
    if (moving)
        m_moving.insert(id);
    else
        m_moving.remove(id);
}

bool MotorRegistry::setSeries(int id, protocol::Series series)
{
    if (!validId(id))
        return false;
    KnownMotor &m = m_motors[id];
    const bool changed = m.id != id || m.series != series;
    m.id = id;
    m.series = series;
    return changed;
}

bool MotorRegistry::learnModel(int id, const protocol::ModelInfo &model,
                               std::optional<protocol::Series> series)
{
    if (!validId(id))
        return false;
    KnownMotor &m = m_motors[id];
    m.id = id;
    m.model = model;
    m.generation = model.generation;
    if (!series)
        series = seriesOf(model); // a model read outside a scan tells it just as well
    if (series)
        m.series = series;
    return true;
}

bool MotorRegistry::learnGeneration(int id, protocol::Generation generation)
{
    if (!validId(id))
        return false;
    KnownMotor &m = m_motors[id];
    const bool changed = m.id != id || (!m.model && m.generation != generation);
    m.id = id;
    if (!m.model)
        m.generation = generation;
    return changed;
}

bool MotorRegistry::setIdentity(int id, protocol::Series series, protocol::Generation generation,
                                std::optional<double> gearRatio)
{
    if (!validId(id))
        return false;
    KnownMotor &m = m_motors[id];
    m.id = id;
    m.series = series;
    m.generation = generation;
    m.gearRatio = gearRatio;
    m.identityChosen = true;
    return true;
}

bool MotorRegistry::learnCanGeneration(int id, protocol::Generation generation)
{
    if (!validId(id))
        return false;
    KnownMotor &m = m_motors[id];
    const bool isNew = m.id != id;
    m.id = id;
    if (m.model || m.identityChosen || (m.generationSeen && m.generation == generation))
        return isNew;
    m.generation = generation;
    m.generationSeen = true;
    return true;
}

std::optional<protocol::Series> MotorRegistry::seriesOf(const protocol::ModelInfo &model)
{
    if (const auto s = motor::ModelNameInfo::parse(model.motorName).series)
        return s;
    return motor::ModelNameInfo::parse(model.driverName).series;
}

bool MotorRegistry::forget(int firstId, int lastId)
{
    bool changed = false;
    for (int id = firstId; id <= lastId; ++id)
        changed = m_motors.remove(id) > 0 || changed;
    return changed;
}

} // namespace lk::bus
