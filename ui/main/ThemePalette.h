#pragma once

#include <QtCore/QString>
#include <QtGui/QPalette>

namespace lk::ui {

/// Fixed dark and light palettes for screenshots and tests (--palette). Normally lkstudio
/// uses the system's palette and style and never sets one of its own.
class ThemePalette {
public:
    static QPalette dark();
    static QPalette light();
    /// Switch the application to the Fusion style with `name` ("dark" or "light");
    /// false (and nothing changed) for any other name.
    static bool apply(const QString &name);
};

} // namespace lk::ui
