#pragma once

#include <QtWidgets/QPushButton>

namespace lk::ui {

/// The big red EMERGENCY STOP button: Motor Off to every drive on the bus (Esc anywhere).
/// It stays enabled in every state: pressing it on a dead link does no harm, and a
/// technician must never have to wonder whether it works.
class EmergencyStopButton : public QPushButton {
    Q_OBJECT
public:
    explicit EmergencyStopButton(QWidget *parent = nullptr);
};

} // namespace lk::ui
