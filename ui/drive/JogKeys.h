#pragma once

#include <QtCore/QObject>

#include <functional>

class QKeyEvent;
class QWidget;

namespace lk::ui {

/// The arrow keys as the jog controls of one view: Left/Right held run a jog that ends on
/// release, Up/Down step. An application event filter, so that it sees the keys wherever the
/// focus is inside the view, but never while the focus is in a text field. The release of the
/// key that started a jog is honoured wherever the focus went, and leaving the application
/// ends the jog (its release will never arrive).
class JogKeys : public QObject {
    Q_OBJECT
public:
    /// What the keys do; the view sends the commands through its own motion gate.
    struct Actions {
        std::function<bool()> enabled;               ///< keyboard jog on, a drive to move
        std::function<bool(int direction)> startJog; ///< true when the jog command went out
        std::function<void()> endJog;
        std::function<void(int direction)> step;
    };

    /// Watches the keys for `scope` (and its children); installs itself on the application.
    JogKeys(QWidget *scope, Actions actions);
    ~JogKeys() override;

    /// The view ended the jog itself (button release, halt): a key release no longer ends it.
    void jogEnded() { m_jogging = false; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    bool handle(QKeyEvent *event);
    static bool focusInTextField();

    QWidget *m_scope;
    Actions m_actions;
    bool m_jogging = false; ///< a jog started by an arrow key runs
};

} // namespace lk::ui
