#include "HelpMenu.h"

#include "AboutDialog.h"
#include "DiagnosticsReport.h"
#include "ShortcutsDialog.h"

#include <panels/BusModel.h>
#include <panels/ConnectionBar.h>

#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QApplication>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QStatusBar>

namespace lk::ui {

namespace {
constexpr int kStatusMs = 5000;
} // namespace

HelpMenu::HelpMenu(BusModel *model, ConnectionBar *bar, QWidget *window)
    : QMenu(tr("&Help"), window), m_model(model), m_bar(bar), m_window(window)
{
    setObjectName(QStringLiteral("helpMenu"));
    addAction(tr("&Keyboard shortcuts"), QKeySequence(Qt::Key_F1), this, &HelpMenu::showShortcuts)
        ->setObjectName(QStringLiteral("shortcutsAction"));
    addAction(tr("Copy &diagnostics"), this, &HelpMenu::copyDiagnostics)
        ->setObjectName(QStringLiteral("copyDiagnosticsAction"));
    addSeparator();
    addAction(tr("&About LK Servo Studio"), this, &HelpMenu::showAbout)
        ->setObjectName(QStringLiteral("aboutAction"));
    addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

QString HelpMenu::diagnostics() const
{
    return DiagnosticsReport::text(
        DiagnosticsReport::gather(*m_model, m_bar->choice(), m_bar->ports()));
}

void HelpMenu::showShortcuts()
{
    auto *dialog = new ShortcutsDialog(m_window, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

void HelpMenu::showAbout()
{
    auto *dialog = new AboutDialog([this] { return diagnostics(); }, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}

void HelpMenu::copyDiagnostics()
{
    QGuiApplication::clipboard()->setText(diagnostics());
    if (auto *main = qobject_cast<QMainWindow *>(m_window))
        main->statusBar()->showMessage(tr("Diagnostics copied to the clipboard"), kStatusMs);
}

} // namespace lk::ui
