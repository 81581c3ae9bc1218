#include "EmergencyStopButton.h"

#include <QtGui/QIcon>

namespace lk::ui {

EmergencyStopButton::EmergencyStopButton(QWidget *parent) : QPushButton(parent)
{
    setObjectName(QStringLiteral("emergencyStop"));
    setText(tr("EMERGENCY STOP (Esc)"));
    setIcon(QIcon(QStringLiteral(":/icons/stop.svg")));
    setIconSize(QSize(28, 28));
    setToolTip(tr("Motor Off (0x80) to every drive on the bus, ahead of everything queued. "
                  "Esc does the same from anywhere in lkstudio."));
    setFocusPolicy(Qt::NoFocus); // never steal focus from what the user is typing
    setMinimumHeight(44);
    setStyleSheet(QStringLiteral(
        "QPushButton#emergencyStop { background: #d32f2f; color: white; font-weight: bold;"
        " font-size: 15px; border: 2px solid #8e0000; border-radius: 6px; padding: 4px 16px; }"
        "QPushButton#emergencyStop:hover { background: #e53935; }"
        "QPushButton#emergencyStop:pressed { background: #9a0007; }"));
}

} // namespace lk::ui
