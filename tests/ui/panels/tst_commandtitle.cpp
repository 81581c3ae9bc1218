// A command goes by a translated human name in the GUI (CommandTitle), never by its
// snake_case CLI.md name, except in the traffic view's command column (CLI.md), whose cells
// and filter give the human name on hover.

#include <drive/DriveText.h>
#include <main/CommandedMotion.h>
#include <panels/BusModel.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>
#include <text/CommandTitle.h>
#include <text/VerdictText.h>

#include <bus/TrafficEvent.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionGuard.h>

#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>

using lk::protocol::Command;
using lk::protocol::CommandTable;
using lk::protocol::Series;
using lk::text::CommandTitle;
using lk::text::VerdictText;

class tst_CommandTitle : public QObject {
    Q_OBJECT
private slots:
    void everyCommandHasAHumanName_data();
    void everyCommandHasAHumanName();
    void motionIsDescribedByName();
    void trafficColumnKeepsCliNamesAndHoversTheTitle();
    void driveViewsNameCommandsByTitle();
    void lkctlVerdictsKeepCliNames();
};

void tst_CommandTitle::everyCommandHasAHumanName_data()
{
    QTest::addColumn<int>("code");
    for (const auto &info : CommandTable::all())
        QTest::newRow(info.name) << int(info.command);
}

void tst_CommandTitle::everyCommandHasAHumanName()
{
    QFETCH(int, code);
    const Command c = Command(code);
    const QString title = CommandTitle::name(c);
    QVERIFY(!title.isEmpty());
    QVERIFY2(!title.contains(QLatin1Char('_')), qPrintable(title));
    QVERIFY(title != CommandTable::name(c));
    QCOMPARE(CommandTitle::withCode(c),
             QStringLiteral("%1 (%2)").arg(title, CommandTable::codeText(quint8(code))));
}

void tst_CommandTitle::motionIsDescribedByName()
{
    QCOMPARE(CommandTitle::name(Command::MultiPositionLimited),
             QStringLiteral("Multi-turn position with speed limit"));
    // A motion command without a value to tell: its title.
    QCOMPARE(lk::ui::CommandedMotion::describe(
                 *lk::protocol::build::plain(Command::MotorRun, 1).request),
             QStringLiteral("Motor Run"));
}

void tst_CommandTitle::trafficColumnKeepsCliNamesAndHoversTheTitle()
{
    lk::ui::TrafficModel model;
    lk::bus::TrafficEvent sent;
    sent.kind = lk::bus::TrafficEvent::Kind::Sent;
    sent.id = 1;
    sent.command = quint8(Command::MultiPositionLimited);
    model.append({sent});
    const QModelIndex cell = model.index(0, lk::ui::TrafficModel::Command);
    QCOMPARE(cell.data().toString(), QStringLiteral("multi_position_limited"));
    QCOMPARE(cell.data(Qt::ToolTipRole).toString(),
             QStringLiteral("Multi-turn position with speed limit (0xA4)"));

    lk::ui::BusModel bus;
    lk::ui::TrafficPanel panel(&bus);
    auto *filter = panel.findChild<QComboBox *>(QStringLiteral("trafficCommandFilter"));
    QVERIFY(filter);
    const int item = filter->findData(int(Command::MultiPositionLimited));
    QVERIFY(item > 0);
    QCOMPARE(filter->itemText(item), QStringLiteral("multi_position_limited (0xA4)"));
    QCOMPARE(filter->itemData(item, Qt::ToolTipRole).toString(),
             QStringLiteral("Multi-turn position with speed limit"));
}

// What the drive views say after sending ("Sent ... to drive 1.") and when the gate refuses:
// the command's title, never its snake_case name.
void tst_CommandTitle::driveViewsNameCommandsByTitle()
{
    QCOMPARE(lk::ui::DriveText::command(Command::MultiPositionLimited),
             CommandTitle::withCode(Command::MultiPositionLimited));
    lk::safety::Verdict unknown;
    unknown.kind = lk::safety::LimitKind::UnknownSeries;
    unknown.command = Command::MultiPositionLimited;
    const QString refusal = lk::ui::DriveText::refusal(unknown, std::nullopt);
    QVERIFY2(!refusal.contains(QStringLiteral("multi_position_limited")), qPrintable(refusal));
    QVERIFY2(refusal.contains(CommandTitle::withCode(Command::MultiPositionLimited)),
             qPrintable(refusal));
    lk::safety::Verdict unsupported;
    unsupported.kind = lk::safety::LimitKind::Unsupported;
    unsupported.command = Command::OpenLoop;
    QCOMPARE(VerdictText::verdict(unsupported, Series::MF),
             QStringLiteral("MF drives do not implement Open loop power (0xA0)"));
}

// lkctl keeps the names of the command line (docs/CLI.md): its main() asks for them.
void tst_CommandTitle::lkctlVerdictsKeepCliNames()
{
    lk::safety::Verdict unsupported;
    unsupported.kind = lk::safety::LimitKind::Unsupported;
    unsupported.command = Command::OpenLoop;
    VerdictText::setCommandNames(VerdictText::CommandNames::Cli);
    const QString cli = VerdictText::verdict(unsupported, Series::MF);
    VerdictText::setCommandNames(VerdictText::CommandNames::Titles);
    QCOMPARE(cli, QStringLiteral("MF drives do not implement open_loop"));
}

QTEST_MAIN(tst_CommandTitle)
#include "tst_commandtitle.moc"
