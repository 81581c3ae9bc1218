#pragma once

#include <QtCore/QString>
#include <QtGui/QColor>
#include <QtGui/QPalette>

namespace lk::ui {

/// The shared status colours (error, warning, info, ok, busy, muted, sent) in a variant that
/// stays readable on the given palette: light tints on a light window, deep tints with light
/// text on a dark one. Call at paint or update time so that a palette change is followed.
class StatusColors {
public:
    enum class Role { Error, Warning, Info, Ok, Busy, Muted, Sent };

    /// The palette's window is dark (lightness below half): the system or --palette is dark.
    static bool isDark(const QPalette &palette);
    /// The application palette (models have no widget of their own).
    static QPalette current();

    /// Text (foreground) in this role, readable on the palette's window and base colours.
    static QColor text(Role role, const QPalette &palette = current());
    /// Background of a box or cell in this role, readable under text() and under the
    /// palette's own text colour.
    static QColor background(Role role, const QPalette &palette = current());
    static QColor border(Role role, const QPalette &palette = current());

    /// Style sheet fragment "color:#rrggbb;" (plus bold when asked).
    static QString textStyle(Role role, const QPalette &palette, bool bold = false);
    /// Style sheet fragment for a message box: background, border, padding.
    static QString boxStyle(Role role, const QPalette &palette);
};

} // namespace lk::ui
