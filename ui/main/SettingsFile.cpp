#include "SettingsFile.h"

#include <QtCore/QFileInfo>
#include <QtCore/QSettings>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>

namespace lk::ui {

SettingsFile::SettingsFile(const QString &iniFile)
    : m_path(iniFile.isEmpty() ? defaultPath() : iniFile), m_problem(check(m_path))
{
    QString used = m_path;
    if (m_problem) {
        // Neither read (it could hang or exhaust memory) nor overwritten (it may be the
        // user's, or a newer release's): the session keeps its settings in a scratch file.
        m_scratch = std::make_unique<QTemporaryDir>();
        used = m_scratch->filePath(QStringLiteral("lkstudio.ini"));
    }
    m_settings = std::make_unique<QSettings>(used, QSettings::IniFormat);
}

SettingsFile::~SettingsFile()
{
    m_settings->sync();
}

QString SettingsFile::defaultPath()
{
    // QSettings(IniFormat, UserScope, "lkstudio", "lkstudio") on XDG systems; computed rather
    // than asked of a QSettings, which would read the file before it is checked.
    return QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) +
           QStringLiteral("/lkstudio/lkstudio.ini");
}

std::optional<system::FileReadError> SettingsFile::check(const QString &path)
{
    if (!QFileInfo(path).exists())
        return std::nullopt; // a first start: QSettings creates it
    system::BoundedRead file = system::BoundedFile::read(path, kMaxBytes);
    return file.error;
}

void SettingsFile::sync()
{
    m_settings->sync();
}

} // namespace lk::ui
