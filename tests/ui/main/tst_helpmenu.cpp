// Help menu: About shows the versions and the licence and copies the diagnostics; the
// shortcuts list comes from the window's own actions (Esc first); Copy diagnostics puts the
// report on the clipboard.

#include <main/AboutDialog.h>
#include <main/AppSettings.h>
#include <main/HelpMenu.h>
#include <main/MainWindow.h>
#include <main/ShortcutsDialog.h>

#include <QtCore/QTemporaryDir>
#include <QtGui/QAction>
#include <QtGui/QClipboard>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableWidget>

using lk::ui::AboutDialog;
using lk::ui::HelpMenu;
using lk::ui::ShortcutsDialog;

class tst_HelpMenu : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanupTestCase();
    void aboutShowsVersionsAndLicence();
    void aboutCopiesDiagnostics();
    void shortcutsComeFromTheActions();
    void helpMenuIsInTheMenuBar();
    void copyDiagnosticsFillsTheClipboard();
    void aboutActionOpensTheDialog();

private:
    HelpMenu *helpMenu() const { return m_window->findChild<HelpMenu *>(); }
    QTemporaryDir m_dir;
    std::unique_ptr<lk::ui::AppSettings> m_settings;
    std::unique_ptr<lk::ui::MainWindow> m_window;
};

void tst_HelpMenu::initTestCase()
{
    QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7"));
    m_settings = std::make_unique<lk::ui::AppSettings>(m_dir.filePath("lkstudio.ini"));
    m_window = std::make_unique<lk::ui::MainWindow>(m_settings.get());
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void tst_HelpMenu::cleanupTestCase()
{
    m_window.reset();
}

void tst_HelpMenu::aboutShowsVersionsAndLicence()
{
    AboutDialog about([] { return QString(); });
    QVERIFY(about.versionsText().contains(QStringLiteral("Qt %1").arg(qVersion())));
    QVERIFY(about.versionsText().contains(QSysInfo::prettyProductName()));
    QVERIFY(about.versionsText().contains(QSysInfo::kernelVersion()));
    QVERIFY(about.licenceText().contains(QStringLiteral("GPL-3.0-or-later")));
    QVERIFY(about.licenceText().contains(QStringLiteral("https://www.gnu.org/licenses/gpl-3.0")));
    const auto labels = about.findChildren<QLabel *>();
    const bool versionShown = std::any_of(labels.cbegin(), labels.cend(), [](const QLabel *l) {
        return l->text().contains(QStringLiteral("LK Servo Studio 9.8.7"));
    });
    QVERIFY(versionShown);
}

void tst_HelpMenu::aboutCopiesDiagnostics()
{
    AboutDialog about([] { return QStringLiteral("the report"); });
    QGuiApplication::clipboard()->clear();
    QTest::mouseClick(about.copyButton(), Qt::LeftButton);
    QCOMPARE(QGuiApplication::clipboard()->text(), QStringLiteral("the report"));
}

void tst_HelpMenu::shortcutsComeFromTheActions()
{
    const QList<ShortcutsDialog::Row> rows = ShortcutsDialog::collect(m_window.get());
    QVERIFY(!rows.isEmpty());
    QCOMPARE(rows.first().keys, QStringLiteral("Esc"));
    const auto has = [&rows](const QString &keys, const QString &what) {
        return std::any_of(rows.cbegin(), rows.cend(), [&](const ShortcutsDialog::Row &r) {
            return r.keys == keys && r.what == what;
        });
    };
    // Every action of the window that has a key is listed (Quit's key depends on the platform).
    for (const QAction *a : m_window->findChildren<QAction *>()) {
        if (!a->shortcut().isEmpty())
            QVERIFY2(has(a->shortcut().toString(QKeySequence::NativeText),
                         a->iconText().remove(QChar(0x2026)).trimmed()),
                     qPrintable(a->text()));
    }
    QVERIFY(has(QStringLiteral("F5"), QStringLiteral("Scan")));
    QVERIFY(has(QStringLiteral("F1"), QStringLiteral("Keyboard shortcuts")));
    QVERIFY(has(QStringLiteral("Ctrl+1"), QStringLiteral("Dashboard")));
    ShortcutsDialog dialog(m_window.get());
    QCOMPARE(dialog.table()->rowCount(), rows.size());
    QCOMPARE(dialog.table()->item(0, 0)->text(), QStringLiteral("Esc"));
}

void tst_HelpMenu::helpMenuIsInTheMenuBar()
{
    QVERIFY(helpMenu());
    const auto menus = m_window->menuBar()->actions();
    QCOMPARE(menus.last()->menu(), helpMenu());
    QStringList texts;
    for (const QAction *a : helpMenu()->actions())
        texts << a->text();
    QVERIFY(texts.contains(QStringLiteral("&Keyboard shortcuts")));
    QVERIFY(texts.contains(QStringLiteral("Copy &diagnostics")));
    QVERIFY(texts.contains(QStringLiteral("&About LK Servo Studio")));
}

void tst_HelpMenu::copyDiagnosticsFillsTheClipboard()
{
    QGuiApplication::clipboard()->clear();
    helpMenu()->findChild<QAction *>(QStringLiteral("copyDiagnosticsAction"))->trigger();
    const QString text = QGuiApplication::clipboard()->text();
    QVERIFY2(text.startsWith(QStringLiteral("LK Servo Studio diagnostics")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("lkstudio 9.8.7")));
    QVERIFY(text.contains(QStringLiteral("Link:")));
}

void tst_HelpMenu::aboutActionOpensTheDialog()
{
    helpMenu()->findChild<QAction *>(QStringLiteral("aboutAction"))->trigger();
    auto *about = m_window->findChild<AboutDialog *>();
    QVERIFY(about);
    QTRY_VERIFY(about->isVisible());
    about->close();
}

QTEST_MAIN(tst_HelpMenu)
#include "tst_helpmenu.moc"
