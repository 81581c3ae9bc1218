#pragma once

#include <panels/ConnectionChoice.h>

#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>
#include <optional>

class QSettings;

namespace lk::ui {

class SettingsFile;

/// The one place lkstudio's settings live: every key is defined once (AppSettings.cpp), read
/// through typed getters that validate what they read, and versioned with a migration step
/// per release so that an upgrade never misreads an older file.
class AppSettings {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::AppSettings)
public:
    /// Layout version written by this build. Bump it and add a step to migrate() whenever a
    /// key changes meaning or name.
    static constexpr int kVersion = 1;

    /// Settings in `file`, which outlives this object and is shared with the other keepers of
    /// settings in the same file (the drive views' store).
    explicit AppSettings(SettingsFile &file);
    /// Settings in a file of their own: `iniFile` (tests), or the user's default file when
    /// empty. file() shares it.
    explicit AppSettings(const QString &iniFile = {});
    ~AppSettings();
    AppSettings(const AppSettings &) = delete;
    AppSettings &operator=(const AppSettings &) = delete;

    QString fileName() const;
    /// The settings file these settings are kept in, for the others kept in it.
    SettingsFile &file() const { return m_file; }
    /// The version of the file as found on disk before migration (0: unversioned or new).
    int loadedVersion() const { return m_loadedVersion; }
    /// The file was written by a newer lkstudio: it is read, never migrated downwards.
    bool isFromNewerRelease() const { return m_loadedVersion > kVersion; }

    /// What was damaged in the file as found at start, one "key: what is wrong" per entry
    /// (a file that cannot be parsed or was not read at all names the file). Those values
    /// are not used.
    QStringList damage() const { return m_damage; }
    /// Translated sentences for the banner: the file was not read (a directory, too large:
    /// SettingsFile::problem()), it comes from a newer release (naming settingsVersion), or
    /// which keys are damaged; empty when none.
    QString damageReport() const;

    ConnectionChoice connection() const;
    void setConnection(const ConnectionChoice &choice);

    /// The series the user chose for drive `id` on `port` (a drive seen only by listening,
    /// whose 0x12 reply never passed); nullopt: none chosen, or the value is damaged.
    std::optional<protocol::Series> chosenSeries(const QString &port, int id) const;
    void setChosenSeries(const QString &port, int id, protocol::Series series);
    /// The CAN generation the user chose for drive `id` on `port` (V2_3: old CAN, V2_35:
    /// V2.36); nullopt when none.
    std::optional<protocol::Generation> chosenGeneration(const QString &port, int id) const;
    void setChosenGeneration(const QString &port, int id, protocol::Generation generation);

    int scanFirstId() const;
    int scanLastId() const;
    bool scanSweepBauds() const;
    void setScanRange(int firstId, int lastId, bool sweepBauds);

    double pollRateHz() const; ///< 0 = as fast as the bus allows
    void setPollRateHz(double hz);

    /// How much the black box keeps (recording/blackBoxMinutes): 1..60 minutes, 10 unless
    /// set. A value outside is damage (named in damage()) and the default is used.
    static constexpr int kMinBlackBoxMinutes = 1;
    static constexpr int kMaxBlackBoxMinutes = 60;
    static constexpr int kDefaultBlackBoxMinutes = 10;
    int blackBoxMinutes() const;
    /// False, and nothing stored, for a value outside 1..60.
    bool setBlackBoxMinutes(int minutes);

    /// The language chosen in the menu ("en", "zh_CN"); empty: follow the system locale.
    QString language() const;
    void setLanguage(const QString &language);

    QString currentView() const; ///< object name of the last central view shown
    void setCurrentView(const QString &name);

    /// The folder last used for files of `purpose` (FileDialogs::purposeKey); empty: none.
    QString lastFolder(const QString &purpose) const;
    void setLastFolder(const QString &purpose, const QString &folder);

    QByteArray windowGeometry() const;
    QByteArray windowState() const;
    void setWindow(const QByteArray &geometry, const QByteArray &state);

    void sync();

    /// Bring `settings` to kVersion in place; returns the version found before. Unknown or
    /// out-of-range values are removed so that the typed getters fall back to defaults.
    static int migrate(QSettings &settings);

private:
    void readFile();
    static QStringList findDamage(QSettings &settings);

    std::unique_ptr<SettingsFile> m_ownFile; ///< only when built from a file name
    SettingsFile &m_file;
    QSettings &m_settings;
    int m_loadedVersion = 0;
    QStringList m_damage;
};

} // namespace lk::ui
