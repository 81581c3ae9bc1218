#pragma once

#include <bus/KnownMotor.h>
#include <safety/SoftLimits.h>

#include <QtCore/QHash>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

class QSettings;

namespace lk::ui {

/// Per-drive settings the drive views keep between sessions: soft limits, encoder
/// resolution and gear ratio, by drive key (see driveKey()). An interface so that lkstudio's
/// settings class can take it over; IniDriveStore keeps them in a QSettings file.
class DriveSettingsStore {
public:
    virtual ~DriveSettingsStore() = default;

    /// The limits stored for the drive, read over `fallback` (missing keys keep its values);
    /// nullopt when none are stored, or when they are damaged: then `error` names the key
    /// and what is wrong (the caller must not replace them silently by defaults).
    virtual std::optional<safety::SoftLimits> softLimits(const QString &driveKey,
                                                         const safety::SoftLimits &fallback,
                                                         QString *error = nullptr) = 0;
    virtual void setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits) = 0;
    virtual std::optional<int> encoderBits(const QString &driveKey) = 0;
    virtual void setEncoderBits(const QString &driveKey, int bits) = 0;
    virtual std::optional<double> gearRatio(const QString &driveKey) = 0;
    virtual void setGearRatio(const QString &driveKey, double ratio) = 0;

    /// "id3-MF4015": the ID and the motor name, so that settings follow a drive and do not
    /// apply to another motor that later sits at the same ID.
    static QString driveKey(int id, const bus::KnownMotor &motor);
};

/// Settings kept for this process only (the default when a view is given no store).
class MemoryDriveStore : public DriveSettingsStore {
public:
    std::optional<safety::SoftLimits> softLimits(const QString &driveKey,
                                                 const safety::SoftLimits &fallback,
                                                 QString *error = nullptr) override;
    void setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits) override;
    std::optional<int> encoderBits(const QString &driveKey) override;
    void setEncoderBits(const QString &driveKey, int bits) override;
    std::optional<double> gearRatio(const QString &driveKey) override;
    void setGearRatio(const QString &driveKey, double ratio) override;

private:
    QHash<QString, safety::SoftLimits> m_limits;
    QHash<QString, int> m_bits;
    QHash<QString, double> m_ratios;
};

/// Settings in a QSettings INI file (group "drives/<key>"); values read back are validated.
class IniDriveStore : public DriveSettingsStore {
public:
    /// Kept in `settings`, which outlives the store: lkstudio's one QSettings on its file
    /// (SettingsFile), shared with AppSettings so that neither loses what the other wrote.
    explicit IniDriveStore(QSettings &settings);

    std::optional<safety::SoftLimits> softLimits(const QString &driveKey,
                                                 const safety::SoftLimits &fallback,
                                                 QString *error = nullptr) override;
    void setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits) override;
    std::optional<int> encoderBits(const QString &driveKey) override;
    void setEncoderBits(const QString &driveKey, int bits) override;
    std::optional<double> gearRatio(const QString &driveKey) override;
    void setGearRatio(const QString &driveKey, double ratio) override;
    void sync();
    /// The settings key of a drive's soft limits ("drives/<key>/softLimits").
    static QString softLimitsKey(const QString &driveKey);
    /// Every damaged drive entry of `settings` as "key: what is wrong" (unknown names, limits
    /// that fail SoftLimits::fromJsonText, unusable resolutions or gear ratios).
    static QStringList damagedEntries(QSettings &settings);

private:
    QSettings &m_settings;
};

} // namespace lk::ui
