#pragma once

#include <QtCore/QObject>

namespace lk::ui {

/// Esc anywhere in the application, including modal dialogs and open pop-ups where the main
/// window's shortcut does not reach: installed on the QApplication, it reports each Esc press
/// once and lets the event go on, so a dialog still closes on Esc. An Esc that the window's
/// QShortcut already took never arrives here as a key press, so nothing fires twice.
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
