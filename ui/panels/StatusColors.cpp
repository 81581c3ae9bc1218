#include "StatusColors.h"

#include <QtGui/QGuiApplication>

namespace lk::ui {

namespace {
struct Shades {
    QRgb text, background, border;
};

// Light: dark text on pale tints. Dark: pale text on deep tints. Contrast of text against
// the window colour of Qt's light and dark palettes is at least 4.5:1 for each.
Shades shades(StatusColors::Role role, bool dark)
{
    using Role = StatusColors::Role;
    switch (role) {
    case Role::Error:
        return dark ? Shades{0xff8a80, 0x5a1e1b, 0xe57373} : Shades{0xb01c16, 0xfde3e1, 0xd9534f};
    case Role::Warning:
        return dark ? Shades{0xffe08a, 0x4d3d0a, 0xc9a227} : Shades{0x6b4c00, 0xfff1c2, 0xd9a400};
    case Role::Info:
        return dark ? Shades{0xbcdcff, 0x1c3350, 0x4a7fb5} : Shades{0x10324f, 0xe3f0fb, 0x7fb2e0};
    case Role::Ok:
        return dark ? Shades{0x81c784, 0x1b3d1e, 0x4caf50} : Shades{0x1e7b34, 0xe3f4e5, 0x4caf50};
    case Role::Busy:
        return dark ? Shades{0x90caf9, 0x1c3350, 0x4a7fb5} : Shades{0x1565c0, 0xe3f0fb, 0x7fb2e0};
    case Role::Sent:
        return dark ? Shades{0x9fc3f5, 0x1c3350, 0x4a7fb5} : Shades{0x1f4e8c, 0xe3f0fb, 0x7fb2e0};
    case Role::Muted:
        break;
    }
    return dark ? Shades{0xa0a0a0, 0x3a3a3a, 0x6a6a6a} : Shades{0x6e6e6e, 0xeeeeee, 0xb0b0b0};
}
} // namespace

bool StatusColors::isDark(const QPalette &palette)
{
    return palette.color(QPalette::Window).lightness() < 128;
}

QPalette StatusColors::current()
{
    return QGuiApplication::palette();
}

QColor StatusColors::text(Role role, const QPalette &palette)
{
    return QColor::fromRgb(shades(role, isDark(palette)).text);
}

QColor StatusColors::background(Role role, const QPalette &palette)
{
    return QColor::fromRgb(shades(role, isDark(palette)).background);
}

QColor StatusColors::border(Role role, const QPalette &palette)
{
    return QColor::fromRgb(shades(role, isDark(palette)).border);
}

QString StatusColors::textStyle(Role role, const QPalette &palette, bool bold)
{
    QString s = QStringLiteral("color:%1;").arg(text(role, palette).name());
    if (bold)
        s += QStringLiteral("font-weight:bold;");
    return s;
}

QString StatusColors::boxStyle(Role role, const QPalette &palette)
{
    return QStringLiteral("background:%1;border:1px solid %2;color:%3;padding:4px;")
        .arg(background(role, palette).name(), border(role, palette).name(),
             text(role, palette).name());
}

} // namespace lk::ui
