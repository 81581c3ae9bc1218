#include "JogKeys.h"

#include <QtGui/QKeyEvent>
#include <QtWidgets/QAbstractSpinBox>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QTextEdit>

namespace lk::ui {

JogKeys::JogKeys(QWidget *scope, Actions actions)
    : QObject(scope), m_scope(scope), m_actions(std::move(actions))
{
    qApp->installEventFilter(this);
}

JogKeys::~JogKeys()
{
    qApp->removeEventFilter(this);
}

bool JogKeys::focusInTextField()
{
    for (QWidget *w = QApplication::focusWidget(); w; w = w->parentWidget()) {
        if (qobject_cast<QLineEdit *>(w) || qobject_cast<QAbstractSpinBox *>(w) ||
            qobject_cast<QTextEdit *>(w) || qobject_cast<QPlainTextEdit *>(w))
            return true;
        if (auto *combo = qobject_cast<QComboBox *>(w); combo && combo->isEditable())
            return true;
    }
    return false;
}

bool JogKeys::handle(QKeyEvent *event)
{
    const int key = event->key();
    if (key != Qt::Key_Left && key != Qt::Key_Right && key != Qt::Key_Up && key != Qt::Key_Down)
        return false;
    if (event->type() == QEvent::KeyRelease) {
        // Always honour a release of the key that started the jog, wherever the focus went.
        if (m_jogging && !event->isAutoRepeat() && (key == Qt::Key_Left || key == Qt::Key_Right)) {
            m_jogging = false;
            m_actions.endJog();
        }
        return m_jogging;
    }
    QWidget *focus = QApplication::focusWidget();
    const bool focusHere = focus && (focus == m_scope || m_scope->isAncestorOf(focus));
    if (!m_actions.enabled() || !focusHere || focusInTextField())
        return false;
    if (event->isAutoRepeat())
        return true; // held key: the jog is already running
    if (key == Qt::Key_Left || key == Qt::Key_Right)
        m_jogging = m_actions.startJog(key == Qt::Key_Left ? -1 : +1);
    else
        m_actions.step(key == Qt::Key_Down ? -1 : +1);
    return true;
}

bool JogKeys::eventFilter(QObject *watched, QEvent *event)
{
    if ((event->type() == QEvent::KeyPress || event->type() == QEvent::KeyRelease) &&
        watched->isWidgetType() && handle(static_cast<QKeyEvent *>(event)))
        return true;
    if (event->type() == QEvent::ApplicationDeactivate && m_jogging) {
        m_jogging = false;
        m_actions.endJog(); // the key release will never arrive here
    }
    return QObject::eventFilter(watched, event);
}

} // namespace lk::ui
