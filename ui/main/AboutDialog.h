#pragma once

#include <QtWidgets/QDialog>

#include <functional>

class QLabel;
class QPushButton;

namespace lk::ui {

/// Help > About: the program's, Qt's and the system's versions, the licence
/// (GPL-3.0-or-later), and "Copy diagnostics" for a bug report.
class AboutDialog : public QDialog {
    Q_OBJECT
public:
    /// `diagnostics` makes the report text when Copy diagnostics is pressed.
    explicit AboutDialog(std::function<QString()> diagnostics, QWidget *parent = nullptr);

    /// The text of the versions block (program, Qt, system), as shown.
    QString versionsText() const;
    QString licenceText() const;
    QPushButton *copyButton() const { return m_copy; }

private:
    std::function<QString()> m_diagnostics;
    QLabel *m_versions = nullptr;
    QLabel *m_licence = nullptr;
    QPushButton *m_copy = nullptr;
};

} // namespace lk::ui
