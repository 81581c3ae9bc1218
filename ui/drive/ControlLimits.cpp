#include "ControlLimits.h"

#include "DriveSettingsStore.h"

#include <protocol/RequestBuilder.h>

#include <QtCore/QStringList>

#include <memory>

namespace lk::ui {

ControlLimits::ControlLimits(Sender sender, QObject *parent)
    : QObject(parent), m_send(std::move(sender)), m_ownStore(std::make_unique<MemoryDriveStore>()),
      m_store(m_ownStore.get())
{
}

ControlLimits::~ControlLimits() = default;

void ControlLimits::setStore(DriveSettingsStore *store)
{
    m_store = store ? store : m_ownStore.get();
    m_key.clear(); // nothing in force came from this store yet
}

QString ControlLimits::load(int id, const bus::KnownMotor &motor,
                            std::optional<protocol::Series> series, const QString &driveTitle)
{
    const safety::SoftLimits defaults = safety::SoftLimits::defaults(series);
    const QString key = id > 0 ? DriveSettingsStore::driveKey(id, motor) : QString();
    QString error;
    const std::optional<safety::SoftLimits> stored =
        id > 0 ? m_store->softLimits(key, defaults, &error) : std::nullopt;
    QString status;
    if (error.isEmpty()) {
        m_soft = stored.value_or(defaults);
        m_problem.clear();
    } else if (key == m_key && m_problem.isEmpty()) {
        // Damaged under our feet: the limits in force stay, never the series defaults.
        status = tr("The soft limits stored for %1 are damaged (%2); the limits in force "
                    "stay. Apply them to store them again.")
                     .arg(driveTitle, error);
    } else {
        // Nothing to keep for this drive: show the defaults as a proposal, send nothing until
        // the user applies limits.
        m_soft = defaults;
        m_problem = damaged(driveTitle, error);
    }
    m_key = key;
    return status;
}

QString ControlLimits::damaged(const QString &driveTitle, const QString &error)
{
    return tr("Refused: the soft limits stored for %1 are damaged (%2). Check and apply the "
              "limits first; nothing sent.")
        .arg(driveTitle, error);
}

std::optional<safety::SoftLimits> ControlLimits::stored(DriveSettingsStore &store, int id,
                                                        const bus::KnownMotor &motor,
                                                        const QString &driveTitle, QString *why)
{
    const safety::SoftLimits defaults = safety::SoftLimits::defaults(motor.series);
    QString error;
    const std::optional<safety::SoftLimits> limits =
        store.softLimits(DriveSettingsStore::driveKey(id, motor), defaults, &error);
    if (!error.isEmpty()) {
        if (why)
            *why = damaged(driveTitle, error);
        return std::nullopt;
    }
    return limits.value_or(defaults);
}

void ControlLimits::apply(int id, const bus::KnownMotor &motor, const safety::SoftLimits &limits)
{
    m_soft = limits;
    m_problem.clear();
    if (id > 0)
        m_store->setSoftLimits(DriveSettingsStore::driveKey(id, motor), limits);
}

void ControlLimits::readDriveLimits(int id, const bus::KnownMotor &motor,
                                    std::optional<protocol::Series> series)
{
    const quint64 read = ++m_reads;
    if (id != m_driveId || m_drive.any()) {
        m_drive = {};
        m_driveId = id;
        emit driveLimitsChanged();
    }
    if (id <= 0 || motor.generation != protocol::Generation::V2_35)
        return;
    const protocol::DecodeContext context{series.value_or(protocol::Series::MF), motor.generation};
    // Every parameter is asked; the limits are taken once all have answered (a max angle needs
    // both halves). One that could not be read bounds nothing: the soft limit stays.
    auto values = std::make_shared<QList<protocol::ParameterValue>>();
    auto left = std::make_shared<int>(int(safety::DriveLimits::params().size()));
    for (protocol::ParamId param : safety::DriveLimits::params()) {
        m_send(*protocol::build::readParam(id, param).request,
               [this, id, read, context, values, left](const bus::RequestResult &r) {
                   const auto *v = replyPayload<protocol::ParameterValue>(r);
                   if (v)
                       values->append(*v);
                   if (--*left > 0 || read != m_reads || id != m_driveId)
                       return;
                   m_drive = safety::DriveLimits::fromParams(*values, context);
                   emit driveLimitsChanged();
               });
    }
}

QString ControlLimits::driveText() const
{
    QStringList parts;
    if (m_drive.maxSpeedDps)
        parts << tr("Max Speed %1 dps").arg(*m_drive.maxSpeedDps, 0, 'g', 8);
    if (m_drive.maxTorqueA)
        parts << tr("max torque current %1 A").arg(*m_drive.maxTorqueA, 0, 'f', 2);
    if (m_drive.maxPower)
        parts << tr("Max Power %1").arg(*m_drive.maxPower);
    if (m_drive.maxAngleDeg)
        parts << tr("Max Angle %1\u00b0").arg(*m_drive.maxAngleDeg, 0, 'g', 10);
    if (parts.isEmpty())
        return QString();
    return tr("The drive's own limits (read from it) also apply where lower: %1.")
        .arg(parts.join(QStringLiteral(", ")));
}

} // namespace lk::ui
