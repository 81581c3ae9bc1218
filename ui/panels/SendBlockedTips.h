#pragma once

#include <QtCore/QString>

class QAbstractButton;
class QWidget;

namespace lk::ui {

/// Tooltips that say why a button is disabled while the link may not transmit (listen-only):
/// every disabled button under a widget shows the reason above its own tooltip; the tooltips
/// come back as they were once sending is allowed again or the button is enabled.
class SendBlockedTips {
public:
    /// `reason` empty: restore every tooltip this replaced under `root`.
    static void apply(QWidget *root, const QString &reason);
    /// The same for one button.
    static void applyTo(QAbstractButton *button, const QString &reason);
};

} // namespace lk::ui
