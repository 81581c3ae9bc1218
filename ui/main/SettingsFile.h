#pragma once

#include <system/BoundedFile.h>

#include <QtCore/QString>

#include <memory>
#include <optional>

class QSettings;
class QTemporaryDir;

namespace lk::ui {

/// The one QSettings open on lkstudio's INI file. Every part of lkstudio that keeps settings
/// (AppSettings, the drive views' IniDriveStore) reads and writes through this one object:
/// two QSettings on one file each write back their own view of it, and one can lose what the
/// other wrote.
///
/// The file is looked at before QSettings reads it: one that is not a regular file (a
/// directory, a FIFO that would hang the start) or larger than kMaxBytes is neither read nor
/// written; the settings then live in memory for the session and problem() says why.
class SettingsFile {
public:
    /// A settings file is a few kilobytes (a dozen keys and a few per drive).
    static constexpr qint64 kMaxBytes = 1024 * 1024;

    /// `iniFile` (tests, --settings), or the user's default file when empty.
    explicit SettingsFile(const QString &iniFile = {});
    ~SettingsFile(); ///< writes what is pending
    SettingsFile(const SettingsFile &) = delete;
    SettingsFile &operator=(const SettingsFile &) = delete;

    /// `$XDG_CONFIG_HOME/lkstudio/lkstudio.ini` (where QSettings keeps the user's INI).
    static QString defaultPath();
    /// Why the file at `path` cannot be the settings file; nullopt when it can (a missing
    /// file can: it is created).
    static std::optional<system::FileReadError> check(const QString &path);

    QSettings &settings() const { return *m_settings; }
    /// The file asked for (also when it was refused and the settings live in memory).
    QString fileName() const { return m_path; }
    /// Why the file was refused; nullopt when the settings are kept in it.
    const std::optional<system::FileReadError> &problem() const { return m_problem; }
    void sync();

private:
    QString m_path;
    std::optional<system::FileReadError> m_problem;
    std::unique_ptr<QTemporaryDir> m_scratch; ///< where refused settings live meanwhile
    std::unique_ptr<QSettings> m_settings;
};

} // namespace lk::ui
