#pragma once

#include <QtCore/QString>
#include <QtGui/QIcon>
#include <QtGui/QPalette>

namespace lk::ui {

/// lkstudio's SVG icons in the variant that suits the palette: on a dark window the icons
/// drawn in dark grey strokes come from their "-dark" twin (light strokes), when there is one.
class ThemedIcon {
public:
    /// `path` is the light icon, e.g. ":/icons/export.svg"; the icon follows the application
    /// palette whenever it is painted (ThemedIconEngine).
    static QIcon get(const QString &path);
    /// The variant for `palette`, fixed.
    static QIcon get(const QString &path, const QPalette &palette);
    /// The resource path get() loads for `palette`.
    static QString pathFor(const QString &path, const QPalette &palette);
    /// The "-dark" twin of `path`, or `path` itself when it has none.
    static QString darkPath(const QString &path);
};

} // namespace lk::ui
