#pragma once

#include <QtWidgets/QMenu>

namespace lk::ui {

class BusModel;
class ConnectionBar;

/// The Help menu: keyboard shortcuts, Copy diagnostics (for a bug report), About.
class HelpMenu : public QMenu {
    Q_OBJECT
public:
    /// `model` and `bar` tell the link, its adapter and the statistics; not owned. The
    /// shortcuts listed are those of `window`.
    HelpMenu(BusModel *model, ConnectionBar *bar, QWidget *window);

    /// The report Copy diagnostics puts on the clipboard.
    QString diagnostics() const;

public slots:
    void showShortcuts();
    void showAbout();
    void copyDiagnostics();

private:
    BusModel *m_model;
    ConnectionBar *m_bar;
    QWidget *m_window;
};

} // namespace lk::ui
