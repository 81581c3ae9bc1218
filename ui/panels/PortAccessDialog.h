#pragma once

#include "SerialGroupAdvice.h"

#include <QtWidgets/QDialog>

class QLineEdit;
class QPushButton;

namespace lk::ui {

/// Tells how to get permission for a serial port: the exact command for this distribution,
/// ready to copy, and that a new login is needed before it applies.
class PortAccessDialog : public QDialog {
    Q_OBJECT
public:
    PortAccessDialog(const QString &port, const SerialGroupAdvice &advice,
                     QWidget *parent = nullptr);

    QString command() const;
    QPushButton *copyButton() const { return m_copy; }

private:
    QLineEdit *m_command = nullptr;
    QPushButton *m_copy = nullptr;
};

} // namespace lk::ui
