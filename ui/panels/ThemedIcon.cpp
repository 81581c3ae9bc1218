#include "ThemedIcon.h"

#include "StatusColors.h"

#include <QtCore/QFile>

namespace lk::ui {

QIcon ThemedIcon::get(const QString &path)
{
    return get(path, StatusColors::current());
}

QIcon ThemedIcon::get(const QString &path, const QPalette &palette)
{
    return QIcon(pathFor(path, palette));
}

QString ThemedIcon::pathFor(const QString &path, const QPalette &palette)
{
    if (!StatusColors::isDark(palette) || !path.endsWith(QLatin1String(".svg")))
        return path;
    QString dark = path;
    dark.insert(dark.size() - 4, QLatin1String("-dark"));
    return QFile::exists(dark) ? dark : path;
}

} // namespace lk::ui
