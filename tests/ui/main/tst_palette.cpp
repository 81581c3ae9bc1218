// Dark and light palettes: the shared status colours contrast with the window and base
// colours of each, and the charts follow a palette change (dark background, light labels).

#include <drive/ControlView.h>
#include <main/ThemePalette.h>
#include <panels/MessageBanner.h>
#include <panels/StatusColors.h>
#include <panels/ThemedIcon.h>
#include <plot/StripChart.h>

#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QPushButton>

#include <cmath>

using lk::ui::StatusColors;
using lk::ui::ThemePalette;
using Role = StatusColors::Role;

Q_DECLARE_METATYPE(StatusColors::Role)

namespace {
// WCAG 2 contrast ratio of two colours (1 .. 21).
double luminance(const QColor &c)
{
    auto channel = [](double v) {
        return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

double contrast(const QColor &a, const QColor &b)
{
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

constexpr double kReadable = 4.5; // WCAG AA for normal text
} // namespace

class tst_Palette : public QObject {
    Q_OBJECT
private slots:
    void cleanupTestCase();
    void statusColorsContrast_data();
    void statusColorsContrast();
    void darkIsDetected();
    void chartFollowsPaletteChange();
    void darkIconTwins_data();
    void darkIconTwins();
    void widgetsFollowLiveSwitch();
};

void tst_Palette::cleanupTestCase()
{
    QApplication::setPalette(ThemePalette::light());
}

void tst_Palette::statusColorsContrast_data()
{
    QTest::addColumn<bool>("dark");
    QTest::addColumn<Role>("role");
    const QList<std::pair<const char *, Role>> roles{
        {"error", Role::Error}, {"warning", Role::Warning}, {"info", Role::Info},  {"ok", Role::Ok},
        {"busy", Role::Busy},   {"sent", Role::Sent},       {"muted", Role::Muted}};
    for (bool dark : {false, true}) {
        for (const auto &[name, role] : roles)
            QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(dark ? "dark" : "light", name)))
                << dark << role;
    }
}

void tst_Palette::statusColorsContrast()
{
    QFETCH(bool, dark);
    QFETCH(Role, role);
    const QPalette p = dark ? ThemePalette::dark() : ThemePalette::light();
    const QColor text = StatusColors::text(role, p);
    // Muted text is secondary on purpose: 3:1 (WCAG for large or secondary text) suffices.
    const double need = role == Role::Muted ? 3.0 : kReadable;
    QVERIFY2(contrast(text, p.color(QPalette::Window)) >= need, qPrintable(text.name()));
    QVERIFY2(contrast(text, p.color(QPalette::Base)) >= need, qPrintable(text.name()));
    // Boxes and cells: both their own text and the palette's text read on the tint.
    const QColor tint = StatusColors::background(role, p);
    QVERIFY2(contrast(text, tint) >= need, qPrintable(tint.name()));
    QVERIFY2(contrast(p.color(QPalette::Text), tint) >= kReadable, qPrintable(tint.name()));
}

void tst_Palette::darkIsDetected()
{
    QVERIFY(StatusColors::isDark(ThemePalette::dark()));
    QVERIFY(!StatusColors::isDark(ThemePalette::light()));
    // The error colour differs between the two: one red does not fit both.
    QVERIFY(StatusColors::text(Role::Error, ThemePalette::dark()) !=
            StatusColors::text(Role::Error, ThemePalette::light()));
}

void tst_Palette::chartFollowsPaletteChange()
{
    QVERIFY(ThemePalette::apply(QStringLiteral("light")));
    lk::ui::StripChart chart;
    chart.resize(400, 300);
    chart.show();
    QVERIFY(QTest::qWaitForWindowExposed(&chart));
    const QColor lightBackground = chart.chart()->backgroundBrush().color();
    QVERIFY2(!StatusColors::isDark(QPalette(lightBackground)), qPrintable(lightBackground.name()));

    QVERIFY(ThemePalette::apply(QStringLiteral("dark")));
    QTRY_VERIFY(chart.chart()->backgroundBrush().color().lightness() < 128);
    const QColor background = chart.chart()->backgroundBrush().color();
    const auto axes = chart.chart()->axes();
    QVERIFY(!axes.isEmpty());
    for (QAbstractAxis *axis : axes) {
        QVERIFY2(contrast(axis->labelsColor(), background) >= kReadable,
                 qPrintable(axis->labelsColor().name()));
        QVERIFY(contrast(axis->gridLineColor(), background) > 1.2); // grid still visible
    }
    QVERIFY(!ThemePalette::apply(QStringLiteral("purple")));
}

void tst_Palette::darkIconTwins_data()
{
    QTest::addColumn<QString>("icon");
    QTest::addColumn<bool>("dark");
    QTest::addColumn<QString>("expected");
    QTest::newRow("light") << ":/icons/export.svg" << false << ":/icons/export.svg";
    QTest::newRow("dark twin") << ":/icons/export.svg" << true << ":/icons/export-dark.svg";
    QTest::newRow("dark overview") << ":/icons/overview.svg" << true << ":/icons/overview-dark.svg";
    QTest::newRow("colour icon, no twin") << ":/icons/stop.svg" << true << ":/icons/stop.svg";
}

void tst_Palette::darkIconTwins()
{
    QFETCH(QString, icon);
    QFETCH(bool, dark);
    QFETCH(QString, expected);
    const QPalette p = dark ? ThemePalette::dark() : ThemePalette::light();
    QCOMPARE(lk::ui::ThemedIcon::pathFor(icon, p), expected);
    QVERIFY(!lk::ui::ThemedIcon::get(icon, p).pixmap(24, 24).isNull());
}

void tst_Palette::widgetsFollowLiveSwitch()
{
    // A desktop switching from light to dark while lkstudio runs: icons made before the switch,
    // the banner's tint and the Motor Off button's red all follow, with nobody rebuilding them.
    QVERIFY(ThemePalette::apply(QStringLiteral("light")));
    const QIcon icon = lk::ui::ThemedIcon::get(QStringLiteral(":/icons/export.svg"));
    const QImage lightDrawing = icon.pixmap(32, 32).toImage();
    QWidget window; // as in the main window: children of a top-level widget
    auto *banner = new lk::ui::MessageBanner(&window);
    banner->showMessage(lk::ui::MessageBanner::Level::Error, QStringLiteral("x"));
    const QString lightSheet = banner->tintStyle();
    auto *control = new lk::ui::ControlView(&window);
    auto *off = control->findChild<QPushButton *>(QStringLiteral("motorOff"));
    QVERIFY(off);
    const QString lightOff = off->styleSheet();

    QVERIFY(ThemePalette::apply(QStringLiteral("dark")));
    const QImage darkDrawing = icon.pixmap(32, 32).toImage();
    QVERIFY(darkDrawing != lightDrawing);
    QCOMPARE(darkDrawing,
             QIcon(QStringLiteral(":/icons/export-dark.svg")).pixmap(32, 32).toImage());
    // The change reaches widgets as posted events: wait for them.
    QTRY_VERIFY(banner->tintStyle() != lightSheet);
    QVERIFY(banner->tintStyle().contains(
        StatusColors::background(Role::Error, ThemePalette::dark()).name()));
    QTRY_VERIFY(off->styleSheet() != lightOff);
    QCOMPARE(off->styleSheet(), StatusColors::textStyle(Role::Error, ThemePalette::dark(), true));
}

QTEST_MAIN(tst_Palette)
#include "tst_palette.moc"
