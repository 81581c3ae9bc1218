#include "DriveSettingsStore.h"

#include <motor/EncoderResolution.h>

#include <QtCore/QJsonDocument>
#include <QtCore/QRegularExpression>
#include <QtCore/QSettings>

#include <algorithm>
#include <iterator>

namespace lk::ui {

namespace {
constexpr double kMaxGearRatio = 1000;

QString keyPath(const QString &driveKey, const char *name)
{
    return QStringLiteral("drives/%1/%2").arg(driveKey, QLatin1String(name));
}

bool validBits(int bits)
{
    return motor::EncoderResolution::choices().contains(bits);
}

bool validRatio(double ratio)
{
    return ratio >= 1.0 && ratio <= kMaxGearRatio;
}
} // namespace

QString DriveSettingsStore::driveKey(int id, const bus::KnownMotor &motor)
{
    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9_.-]+"));
    QString key = QStringLiteral("id%1").arg(id);
    if (motor.model && !motor.model->motorName.trimmed().isEmpty())
        key += QLatin1Char('-') +
               motor.model->motorName.trimmed().replace(unsafe, QStringLiteral("_"));
    return key;
}

std::optional<safety::SoftLimits>
MemoryDriveStore::softLimits(const QString &driveKey, const safety::SoftLimits &, QString *)
{
    const auto it = m_limits.constFind(driveKey);
    if (it == m_limits.constEnd())
        return std::nullopt;
    return *it;
}

void MemoryDriveStore::setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits)
{
    m_limits.insert(driveKey, limits);
}

std::optional<int> MemoryDriveStore::encoderBits(const QString &driveKey)
{
    const auto it = m_bits.constFind(driveKey);
    return it == m_bits.constEnd() ? std::nullopt : std::optional<int>(*it);
}

void MemoryDriveStore::setEncoderBits(const QString &driveKey, int bits)
{
    if (validBits(bits))
        m_bits.insert(driveKey, bits);
}

std::optional<double> MemoryDriveStore::gearRatio(const QString &driveKey)
{
    const auto it = m_ratios.constFind(driveKey);
    return it == m_ratios.constEnd() ? std::nullopt : std::optional<double>(*it);
}

void MemoryDriveStore::setGearRatio(const QString &driveKey, double ratio)
{
    if (validRatio(ratio))
        m_ratios.insert(driveKey, ratio);
}

IniDriveStore::IniDriveStore(QSettings &settings) : m_settings(settings) {}

std::optional<safety::SoftLimits> IniDriveStore::softLimits(const QString &driveKey,
                                                            const safety::SoftLimits &fallback,
                                                            QString *error)
{
    const QString key = softLimitsKey(driveKey);
    if (!m_settings.contains(key))
        return std::nullopt;
    // An INI value with unquoted commas reads back as a list: rejoin it for the JSON check.
    const QVariant value = m_settings.value(key);
    const QString text = value.typeId() == QMetaType::QStringList
                             ? value.toStringList().join(QLatin1Char(','))
                             : value.toString();
    QString problem;
    const std::optional<safety::SoftLimits> limits =
        safety::SoftLimits::fromJsonText(text.toUtf8(), fallback, &problem);
    if (!limits && error)
        *error = QStringLiteral("%1: %2").arg(key, problem);
    return limits;
}

QString IniDriveStore::softLimitsKey(const QString &driveKey)
{
    return keyPath(driveKey, "softLimits");
}

void IniDriveStore::setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits)
{
    m_settings.setValue(
        keyPath(driveKey, "softLimits"),
        QString::fromUtf8(QJsonDocument(limits.toJson()).toJson(QJsonDocument::Compact)));
}

std::optional<int> IniDriveStore::encoderBits(const QString &driveKey)
{
    bool ok = false;
    const int bits = m_settings.value(keyPath(driveKey, "encoderBits")).toInt(&ok);
    return ok && validBits(bits) ? std::optional<int>(bits) : std::nullopt;
}

void IniDriveStore::setEncoderBits(const QString &driveKey, int bits)
{
    if (validBits(bits))
        m_settings.setValue(keyPath(driveKey, "encoderBits"), bits);
}

std::optional<double> IniDriveStore::gearRatio(const QString &driveKey)
{
    bool ok = false;
    const double ratio = m_settings.value(keyPath(driveKey, "gearRatio")).toDouble(&ok);
    return ok && validRatio(ratio) ? std::optional<double>(ratio) : std::nullopt;
}

void IniDriveStore::setGearRatio(const QString &driveKey, double ratio)
{
    if (validRatio(ratio))
        m_settings.setValue(keyPath(driveKey, "gearRatio"), ratio);
}

QStringList IniDriveStore::damagedEntries(QSettings &settings)
{
    QStringList damaged;
    settings.beginGroup(QStringLiteral("drives"));
    const QStringList drives = settings.childGroups();
    settings.endGroup();
    for (const QString &drive : drives) {
        settings.beginGroup(QStringLiteral("drives/") + drive);
        const QStringList keys = settings.childKeys();
        settings.endGroup();
        for (const QString &name : keys) {
            const QString key = QStringLiteral("drives/%1/%2").arg(drive, name);
            const QVariant v = settings.value(key);
            bool ok = false;
            if (name == QLatin1String("softLimits")) {
                const QString text = v.typeId() == QMetaType::QStringList
                                         ? v.toStringList().join(QLatin1Char(','))
                                         : v.toString();
                QString problem;
                if (!safety::SoftLimits::fromJsonText(text.toUtf8(), safety::SoftLimits{},
                                                      &problem))
                    damaged << QStringLiteral("%1: %2").arg(key, problem);
            } else if (name == QLatin1String("encoderBits")) {
                if (!validBits(v.toInt(&ok)) || !ok)
                    damaged << QStringLiteral("%1: must be one of 12, 14, 15, 16, 18").arg(key);
            } else if (name == QLatin1String("gearRatio")) {
                if (!validRatio(v.toDouble(&ok)) || !ok)
                    damaged << QStringLiteral("%1: must be a number in 1..%2")
                                   .arg(key)
                                   .arg(kMaxGearRatio);
            } else {
                damaged << QStringLiteral("%1: unknown key").arg(key);
            }
        }
    }
    return damaged;
}

void IniDriveStore::sync()
{
    m_settings.sync();
}

} // namespace lk::ui
