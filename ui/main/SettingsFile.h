#pragma once

#include <QtCore/QString>

#include <memory>

class QSettings;

namespace lk::ui {

/// The one QSettings open on lkstudio's INI file. Every part of lkstudio that keeps settings
/// (AppSettings, the drive views' IniDriveStore) reads and writes through this one object:
/// two QSettings on one file each write back their own view of it, and one can lose what the
/// other wrote.
class SettingsFile {
public:
    /// `iniFile` (tests, --settings), or the user's default file when empty.
    explicit SettingsFile(const QString &iniFile = {});
    ~SettingsFile(); ///< writes what is pending
    SettingsFile(const SettingsFile &) = delete;
    SettingsFile &operator=(const SettingsFile &) = delete;

    QSettings &settings() const { return *m_settings; }
    QString fileName() const;
    void sync();

private:
    std::unique_ptr<QSettings> m_settings;
};

} // namespace lk::ui
