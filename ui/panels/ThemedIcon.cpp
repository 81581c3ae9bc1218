#include "ThemedIcon.h"

#include "StatusColors.h"
#include "ThemedIconEngine.h"

#include <QtCore/QFile>

namespace lk::ui {

QIcon ThemedIcon::get(const QString &path)
{
    const QString dark = darkPath(path);
    if (dark == path)
        return QIcon(path);
    // Chosen at paint time: the icon follows a palette change while the program runs.
    return QIcon(new ThemedIconEngine(QIcon(path), QIcon(dark)));
}

QIcon ThemedIcon::get(const QString &path, const QPalette &palette)
{
    return QIcon(pathFor(path, palette));
}

QString ThemedIcon::pathFor(const QString &path, const QPalette &palette)
{
    return StatusColors::isDark(palette) ? darkPath(path) : path;
}

QString ThemedIcon::darkPath(const QString &path)
{
    if (!path.endsWith(QLatin1String(".svg")))
        return path;
    QString dark = path;
    dark.insert(dark.size() - 4, QLatin1String("-dark"));
    return QFile::exists(dark) ? dark : path;
}

} // namespace lk::ui
