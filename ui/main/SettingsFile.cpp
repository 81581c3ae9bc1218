#include "SettingsFile.h"

#include <QtCore/QSettings>

namespace lk::ui {

SettingsFile::SettingsFile(const QString &iniFile)
    : m_settings(iniFile.isEmpty() ? std::make_unique<QSettings>(
                                         QSettings::IniFormat, QSettings::UserScope,
                                         QStringLiteral("lkstudio"), QStringLiteral("lkstudio"))
                                   : std::make_unique<QSettings>(iniFile, QSettings::IniFormat))
{
}

SettingsFile::~SettingsFile()
{
    m_settings->sync();
}

QString SettingsFile::fileName() const
{
    return m_settings->fileName();
}

void SettingsFile::sync()
{
    m_settings->sync();
}

} // namespace lk::ui
