#include "ThemedIcon.h"

#include "StatusColors.h"
#include "ThemedIconEngine.h"

#include <QtCore/QFile>
#include <QtCore/QHash>

namespace lk::ui {

QIcon ThemedIcon::get(const QString &path)
{
    // One icon per path for the program's life (GUI thread only): views refresh several
    // times a second, and a new icon each time meant a resource lookup and an SVG render.
    static QHash<QString, QIcon> cache;
    if (const auto it = cache.constFind(path); it != cache.constEnd())
        return *it;
    const QString dark = darkPath(path);
    // Chosen at paint time: the icon follows a palette change while the program runs.
    const QIcon icon =
        dark == path ? QIcon(path) : QIcon(new ThemedIconEngine(QIcon(path), QIcon(dark)));
    cache.insert(path, icon);
    return icon;
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
