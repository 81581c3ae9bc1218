#include "EmergencyKeyFilter.h"

#include <QtCore/QTimer>
#include <QtGui/QKeyEvent>

namespace lk::ui {

bool EmergencyKeyFilter::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<const QKeyEvent *>(event);
        if (key->key() == Qt::Key_Escape && !key->isAutoRepeat()) {
            if (event != m_current) {
                m_current = event;
                QTimer::singleShot(0, this, [this] { m_current = nullptr; });
                emit escapePressed();
            }
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace lk::ui
