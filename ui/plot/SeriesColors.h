#pragma once

#include <QtGui/QColor>

namespace lk::ui {

/// The line colours every chart cycles through (drives, channels, step-test runs), chosen to
/// stay apart on light and dark backgrounds.
class SeriesColors {
public:
    static constexpr int kCount = 8;
    /// Colour `index` modulo kCount.
    static QColor at(int index);
};

} // namespace lk::ui
