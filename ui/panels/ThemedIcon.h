#pragma once

#include <QtCore/QString>
#include <QtGui/QIcon>
#include <QtGui/QPalette>

namespace lk::ui {

/// lkstudio's SVG icons in the variant that suits the palette: on a dark window the icons
/// drawn in dark grey strokes come from their "-dark" twin (light strokes), when there is one.
class ThemedIcon {
public:
    /// `path` is the light icon, e.g. ":/icons/export.svg".
    static QIcon get(const QString &path);
    static QIcon get(const QString &path, const QPalette &palette);
    /// The resource path get() loads for `palette`.
    static QString pathFor(const QString &path, const QPalette &palette);
};

} // namespace lk::ui
