#pragma once

#include <QtCore/QObject>

namespace lk::ui {

/// Esc anywhere in the application, including modal dialogs and open pop-ups: installed on
/// the QApplication by EmergencyStopControl (the only place Esc is handled), it reports each
/// Esc press once and lets the event go on, so a dialog still closes on Esc. Nothing in
/// lkstudio binds Esc as a shortcut, so every press arrives here as a key press.
class EmergencyKeyFilter : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

signals:
    void escapePressed();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /// The press being delivered: a key event propagating to parent widgets passes the
    /// filter again within the same delivery; cleared when the event loop runs again.
    const QEvent *m_current = nullptr;
};

} // namespace lk::ui
