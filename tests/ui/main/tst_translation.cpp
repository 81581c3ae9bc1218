// lkstudio in Simplified Chinese: with the zh_CN translator installed, every view of the
// main window, on the built-in simulated bus with a drive selected, shows no English word
// outside a short allow-list (catches strings that bypass tr() or lack a translation). Also:
// the window fits a 1366x768 screen (minus a taskbar) in both languages.

#include "EnglishTextFinder.h"

#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/LanguageLoader.h>
#include <main/LanguageMenu.h>
#include <main/MainWindow.h>
#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>
#include <plot/PlotPanel.h>

#include <QtCore/QTemporaryDir>
#include <QtGui/QScreen>
#include <QtTest/QtTest>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QScrollArea>
#include <QtWidgets/QScrollBar>
#include <QtWidgets/QTabWidget>

#include <memory>

using lk::ui::LanguageLoader;
using lk::ui::MainWindow;

namespace {
constexpr int kWaitMs = 20000;       // generous: a loaded 2-core CI machine
const QSize kSmallScreen(1366, 728); // 1366x768 minus a 40-pixel taskbar

// The traffic log's raw bytes and command names are protocol data, the same in every language
// (the decoded fields beside them are translated, and checked).
void ignoreProtocolColumns(EnglishTextFinder &finder)
{
    finder.ignoreColumn(QCoreApplication::translate("lk::ui::TrafficModel", "Raw bytes"));
    finder.ignoreColumn(QCoreApplication::translate("lk::ui::TrafficModel", "Command"));
    finder.ignoreIdentifierList(QStringLiteral("trafficCommandFilter"));
}
} // namespace

class tst_Translation : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanupTestCase();
    void resolvesLanguage_data();
    void resolvesLanguage();
    void finderCatchesEnglish();
    void languageMenuNamesEachLanguageInItself();
    void everyViewIsChinese_data();
    void everyViewIsChinese();
    void menusAreChinese();
    void fitsSmallScreen_data();
    void fitsSmallScreen();
    void opensWithinTheScreen();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<lk::ui::AppSettings> m_settings;
    std::unique_ptr<MainWindow> m_window;
};

void tst_Translation::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY2(LanguageLoader::install(QStringLiteral("zh_CN")), "no :/i18n/lkstudio_zh_CN.qm");
    m_settings = std::make_unique<lk::ui::AppSettings>(m_dir.filePath(QStringLiteral("a.ini")));
    m_window = std::make_unique<MainWindow>(m_settings.get());
    m_window->resize(1366, 728);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    lk::ui::ConnectionChoice c;
    c.kind = lk::ui::ConnectionChoice::Kind::Simulator;
    c.autoReconnect = false;
    m_window->connectTo(c);
    auto *model = m_window->busModel();
    QTRY_COMPARE_WITH_TIMEOUT(model->ids().size(), 4, kWaitMs);
    model->setCurrentId(1);
    QTRY_VERIFY_WITH_TIMEOUT(model->isPolling(), kWaitMs);
}

void tst_Translation::cleanupTestCase()
{
    m_window.reset();
    LanguageLoader::uninstall();
}

void tst_Translation::resolvesLanguage_data()
{
    QTest::addColumn<QString>("preferred");
    QTest::addColumn<QStringList>("system");
    QTest::addColumn<QString>("expected");
    QTest::newRow("setting wins") << "zh_CN" << QStringList{"en-US"} << "zh_CN";
    QTest::newRow("system Chinese") << "" << QStringList{"zh-Hans-CN", "zh-CN"} << "zh_CN";
    QTest::newRow("system Chinese short") << "" << QStringList{"zh"} << "zh_CN";
    QTest::newRow("system English") << "" << QStringList{"en-GB"} << "en";
    QTest::newRow("unknown falls to next") << "" << QStringList{"de-DE", "zh-CN"} << "zh_CN";
    QTest::newRow("unknown falls to English") << "" << QStringList{"de-DE", "fr-FR"} << "en";
    QTest::newRow("traditional not shipped") << "" << QStringList{"zh-Hant-TW"} << "en";
    QTest::newRow("unknown setting ignored") << "xx" << QStringList{"zh-CN"} << "zh_CN";
}

void tst_Translation::resolvesLanguage()
{
    QFETCH(QString, preferred);
    QFETCH(QStringList, system);
    QFETCH(QString, expected);
    QCOMPARE(LanguageLoader::resolve(preferred, system), expected);
}

void tst_Translation::finderCatchesEnglish()
{
    // The check must be able to fail: an untranslated label is reported, allowed words not.
    EnglishTextFinder finder;
    QCOMPARE(finder.englishWords(QStringLiteral("写入 RAM，ID 3，12.5 dps，MG5010E-i36")),
             QStringList());
    QCOMPARE(finder.englishWords(QStringLiteral("<b>Drive</b> 3 &Scan")),
             (QStringList{"Drive", "Scan"}));
    QWidget w;
    auto *label = new QLabel(QStringLiteral("Untranslated"), &w);
    label->setToolTip(QStringLiteral("提示"));
    finder.walk(&w);
    QCOMPARE(finder.findings().size(), 1);
    QVERIFY(finder.findings().first().contains(QStringLiteral("Untranslated")));
}

void tst_Translation::languageMenuNamesEachLanguageInItself()
{
    lk::ui::AppSettings settings(m_dir.filePath(QStringLiteral("menu.ini")));
    settings.setLanguage(QStringLiteral("zh_CN"));
    lk::ui::LanguageMenu menu(&settings);
    QStringList texts;
    for (QAction *a : menu.actions()) {
        if (!a->isSeparator())
            texts << a->text();
    }
    QCOMPARE(texts, (QStringList{QStringLiteral("跟随系统"), QStringLiteral("English"),
                                 QStringLiteral("简体中文")}));
    QCOMPARE(menu.checkedLanguage(), QStringLiteral("zh_CN"));
    QCOMPARE(menu.title(), QStringLiteral("语言(&L)"));
}

void tst_Translation::everyViewIsChinese_data()
{
    QTest::addColumn<QString>("view");
    for (const QString &name : m_window->viewNames())
        QTest::newRow(qPrintable(name)) << name;
}

void tst_Translation::everyViewIsChinese()
{
    QFETCH(QString, view);
    QVERIFY(m_window->showView(view));
    // Let the view fill in: live values, drive names, plot axes.
    QTest::qWait(1500);
    EnglishTextFinder finder;
    ignoreProtocolColumns(finder);
    finder.walk(m_window->currentView());
    QVERIFY2(finder.findings().isEmpty(), qPrintable(finder.findings().join(QLatin1Char('\n'))));
    QVERIFY2(finder.checkedCount() >= 10, qPrintable(QString::number(finder.checkedCount())));
}

void tst_Translation::menusAreChinese()
{
    // The whole window: menus, toolbar, bus dock, status bar, banner, and every view again.
    EnglishTextFinder finder;
    ignoreProtocolColumns(finder);
    finder.walk(m_window.get());
    QVERIFY2(finder.findings().isEmpty(), qPrintable(finder.findings().join(QLatin1Char('\n'))));
    QVERIFY(m_window->menuBar()->actions().first()->text().contains(QStringLiteral("文件")));
}

void tst_Translation::fitsSmallScreen_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<bool>("can");
    QTest::newRow("en") << "en" << false;
    QTest::newRow("zh_CN") << "zh_CN" << false;
    // On CAN the connection bar holds a plugin, an interface and a bit rate, and the bus panel
    // a series, a generation and a gear ratio: both wider than their RS485 forms.
    QTest::newRow("en CAN") << "en" << true;
    QTest::newRow("zh_CN CAN") << "zh_CN" << true;
}

void tst_Translation::fitsSmallScreen()
{
    QFETCH(QString, language);
    QFETCH(bool, can);
    LanguageLoader::install(language);
    lk::ui::AppSettings settings(m_dir.filePath(QStringLiteral("fit-%1.ini").arg(language)));
    MainWindow window(&settings);
    const QSize hint = window.minimumSizeHint();
    QVERIFY2(hint.width() <= kSmallScreen.width() && hint.height() <= kSmallScreen.height(),
             qPrintable(QStringLiteral("minimum %1x%2").arg(hint.width()).arg(hint.height())));
    // Every view sits in a scroll area, so the window's minimum alone proves little: at the
    // small screen's size no view may need to scroll sideways (a clipped panel would).
    window.resize(kSmallScreen);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // The heaviest content a user can ask for: four drives polled, all selected, every
    // signal plotted, the bus limit known (its text is the longest in the Plots toolbar).
    lk::ui::ConnectionChoice c;
    c.kind = lk::ui::ConnectionChoice::Kind::Simulator;
    c.simulatedCan = can;
    c.autoReconnect = false;
    window.connectTo(c);
    auto *model = window.busModel();
    QTRY_COMPARE_WITH_TIMEOUT(model->ids().size(), 4, kWaitMs);
    model->setSelectedIds(model->ids());
    // The stop button must never go behind the toolbar's overflow arrow, whatever the link.
    auto *stop = window.findChild<QWidget *>(QStringLiteral("emergencyStop"));
    QVERIFY(stop);
    QVERIFY2(stop->isVisible() &&
                 window.rect().contains(QRect(stop->mapTo(&window, QPoint()), stop->size())),
             "the emergency stop button is hidden in the toolbar's overflow");
    // ... nor push the window past the screen (a link's longer connection bar could).
    QVERIFY2(window.minimumSizeHint().width() <= kSmallScreen.width(),
             qPrintable(QStringLiteral("minimum width %1").arg(window.minimumSizeHint().width())));
    for (const auto channel : lk::ui::PlotPanel::pickableChannels())
        window.plots()->setChannelVisible(channel, true);
    QTRY_VERIFY_WITH_TIMEOUT(model->statistics().pollLimitPerSecond > 0, kWaitMs);
    for (const QString &name : window.viewNames()) {
        QVERIFY(window.showView(name));
        QTest::qWait(100); // a redraw and a statistics update land
        auto *page =
            qobject_cast<QScrollArea *>(window.currentView()->parentWidget()->parentWidget());
        QVERIFY2(page, qPrintable(name));
        QVERIFY2(!page->horizontalScrollBar()->isVisible(),
                 qPrintable(QStringLiteral("%1 scrolls sideways at %2 wide: its minimum is %3")
                                .arg(name)
                                .arg(kSmallScreen.width())
                                .arg(window.currentView()->minimumSizeHint().width())));
    }
    LanguageLoader::install(QStringLiteral("zh_CN"));
}

// Without a saved geometry the window opens at its default size, bounded by the screen's free
// area (it opened at 1400x900 on a 1366x768 laptop), never below its own minimum.
void tst_Translation::opensWithinTheScreen()
{
    lk::ui::AppSettings settings(m_dir.filePath(QStringLiteral("fresh.ini")));
    MainWindow window(&settings);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QSize free = window.screen()->availableGeometry().size();
    const QSize expected = QSize(1400, 900).boundedTo(free).expandedTo(window.minimumSizeHint());
    QCOMPARE(window.size(), expected);
}

QTEST_MAIN(tst_Translation)
#include "tst_translation.moc"
