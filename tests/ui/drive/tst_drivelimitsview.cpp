#include "ParamTestHelpers.h"

#include <drive/ConfirmDialog.h>
#include <drive/DriveLimitSet.h>
#include <drive/DriveLimitsView.h>
#include <drive/ParameterTable.h>
#include <drive/TuningView.h>
#include <sim/FaultInjector.h>
#include <sim/SimBus.h>

#include <QtTest/QtTest>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>

using lk::drivetest::heldText;
using lk::drivetest::kWaitMs;
using lk::drivetest::paramWrites;
using lk::drivetest::ramParams;
using lk::drivetest::romParams;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::sim::SimParams;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::DriveLimitsView;
using Limit = lk::ui::DriveLimitSet;

namespace {

/// A limits view on drive `id`, shown, with its first read finished (answered or not).
std::unique_ptr<DriveLimitsView> openView(SimRig &rig, int id)
{
    auto view = lk::drivetest::showView<DriveLimitsView>(rig, id, QSize(600, 600));
    if (!QTest::qWaitFor([&] { return !view->isBusy(); }, kWaitMs))
        return nullptr;
    return view;
}

void edit(DriveLimitsView &view, int row, const QString &value)
{
    lk::drivetest::typeInto(view.table()->editor(row), value);
}

QPushButton *button(DriveLimitsView &view, const char *name)
{
    return view.findChild<QPushButton *>(QLatin1String(name));
}

bool waitIdle(DriveLimitsView &view)
{
    return QTest::qWaitFor([&] { return !view.isBusy(); }, kWaitMs);
}

constexpr qint64 kWideAngle = 5000000000; // 0.01 deg: needs both halves (> 2^32)

} // namespace

class tst_DriveLimitsView : public QObject {
    Q_OBJECT
private slots:
    void readsEveryLimitAsPair();
    void nothingWritableBeforeRead();
    void ramWriteSendsChangedAndPair();
    void romWriteAsksAndSendsEachOnce();
    void refusedWriteIsShown();
    void v23DriveHasNoLimits();
    void tuningViewHasLimitsTab();
    void zeroIsAValueAndFirstReadIsShown();
};

void tst_DriveLimitsView::readsEveryLimitAsPair()
{
    SimRig rig(QStringLiteral("1:MS4015@2.35,2:MF@2.35"));
    QVERIFY(rig.open());
    rig.withDrive(1, [](lk::sim::SimDrive &d) {
        d.handle(*lk::protocol::build::writeParam(1, lk::protocol::ParamId::MaxAngleLow,
                                                  kWideAngle * 0.01, false)
                      .request);
        d.handle(*lk::protocol::build::writeParam(1, lk::protocol::ParamId::MaxAngleHigh,
                                                  kWideAngle * 0.01, false)
                      .request);
    });
    auto view = openView(rig, 1);
    QVERIFY(view);
    QVERIFY(view->readComplete());
    const SimParams p = ramParams(rig, 1);
    const lk::ui::ParamValues expected{p.maxTorque, p.maxSpeedRaw, kWideAngle, p.currentRamp,
                                       p.speedRampDps2};
    QCOMPARE(*view->table()->pending(), expected);
    QCOMPARE(heldText(*view->table(), Limit::MaxAngle), QStringLiteral("50000000.00 deg"));
    QCOMPARE(view->table()->field(Limit::MaxTorque).name, QStringLiteral("Max power (0x99)"));
    QCOMPARE(rig.count(1, Command::ReadParam), 6); // 0x9B and 0x9C both
    QVERIFY(button(*view, "limitsWriteRam")->isEnabled());

    view->setDrive(2, rig.motor(2)); // MF: torque current, not power
    QVERIFY(waitIdle(*view) && view->readComplete());
    QCOMPARE(view->table()->field(Limit::MaxTorque).name,
             QStringLiteral("Max torque current (0x99)"));
}

void tst_DriveLimitsView::nothingWritableBeforeRead()
{
    SimRig rig(QStringLiteral("1:MF@2.35"));
    QVERIFY(rig.open());
    // The first 0x40's reply is lost twice (one retry); every other reply comes.
    rig.sim->withBus([](lk::sim::SimBus &bus) {
        bus.faults().dropNextRepliesTo(quint8(Command::ReadParam), 1, 2);
    });
    auto view = openView(rig, 1);
    QVERIFY(view);
    QVERIFY(!view->readComplete());
    QVERIFY(!view->table()->pending());
    QVERIFY(!view->driveValues().at(Limit::MaxTorque)); // unknown, never 0
    for (int r = 0; r < view->table()->rowCount(); ++r) {
        QCOMPARE(view->table()->editor(r)->text(), QStringLiteral("unknown"));
        QVERIFY(!view->table()->editor(r)->isEnabled());
    }
    QVERIFY(!button(*view, "limitsWriteRam")->isEnabled());
    QVERIFY(!button(*view, "limitsWriteRom")->isEnabled());
    int asked = 0;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &) { return ++asked > 0; });
    view->writeToRam();
    view->writeToRom();
    QVERIFY(rig.barrier());
    QCOMPARE(paramWrites(rig, 1), 0);
    QCOMPARE(asked, 0);
    QVERIFY(view->statusText().contains(QStringLiteral("Nothing was sent")));
}

void tst_DriveLimitsView::ramWriteSendsChangedAndPair()
{
    SimRig rig(QStringLiteral("1:MF@2.35"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    const SimParams rom = romParams(rig, 1);
    edit(*view, Limit::MaxAngle, QStringLiteral("50000000"));
    QVERIFY(view->table()->isChanged(Limit::MaxAngle));
    QTest::mouseClick(button(*view, "limitsWriteRam"), Qt::LeftButton);
    QVERIFY(waitIdle(*view));
    QCOMPARE(rig.count(1, Command::WriteParamRam), 2); // only the changed limit, as a pair
    QCOMPARE(ramParams(rig, 1).maxAngleRaw, kWideAngle);
    QCOMPARE(romParams(rig, 1), rom);
    QCOMPARE(view->driveValues().at(Limit::MaxAngle), std::optional<qint64>(kWideAngle));
    QCOMPARE(rig.count(1, Command::ReadParam), 12); // read, then read back (both halves)
    QVERIFY(view->mismatchText().isEmpty());
    QVERIFY2(view->statusText().contains(QStringLiteral("read back")),
             qPrintable(view->statusText()));

    edit(*view, Limit::MaxSpeed, QStringLiteral("123.45"));
    view->writeToRam();
    QVERIFY(waitIdle(*view));
    QCOMPARE(ramParams(rig, 1).maxSpeedRaw, 12345); // 0.01 dps on the wire
    QCOMPARE(rig.count(1, Command::WriteParamRam), 3);

    view->writeToRam(); // nothing differs: nothing to send, and it says so
    QVERIFY(rig.barrier());
    QCOMPARE(rig.count(1, Command::WriteParamRam), 3);
    QVERIFY2(view->statusText().contains(QStringLiteral("does not differ")),
             qPrintable(view->statusText()));
}

void tst_DriveLimitsView::romWriteAsksAndSendsEachOnce()
{
    SimRig rig(QStringLiteral("1:MF@2.35"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    edit(*view, Limit::SpeedRamp, QStringLiteral("5000"));
    QList<ConfirmRequest> asked;
    bool answer = false;
    ConfirmDialog::ScopedPolicy policy([&](const ConfirmRequest &q) {
        asked << q;
        return answer;
    });
    view->writeToRom();
    QVERIFY(rig.barrier());
    QCOMPARE(asked.size(), 1);
    QVERIFY(asked.first().reason.contains(QStringLiteral("wear")));
    QCOMPARE(paramWrites(rig, 1), 0);
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));

    answer = true;
    view->writeToRom();
    QVERIFY(waitIdle(*view));
    QCOMPARE(rig.count(1, Command::WriteParamRom), 6); // five limits, the angle as a pair
    QCOMPARE(rig.count(1, Command::WriteParamRam), 0);
    QCOMPARE(romParams(rig, 1).speedRampDps2, 5000);
    QCOMPARE(romParams(rig, 1), ramParams(rig, 1));
    QCOMPARE(view->driveValues().at(Limit::SpeedRamp), std::optional<qint64>(5000));
    QVERIFY2(view->statusText().contains(QStringLiteral("ROM")), qPrintable(view->statusText()));
}

void tst_DriveLimitsView::refusedWriteIsShown()
{
    SimRig rig(QStringLiteral("1:MF@2.35+param-write-refused"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    edit(*view, Limit::CurrentRamp, QStringLiteral("100"));
    view->writeToRam();
    QVERIFY(waitIdle(*view));
    QVERIFY2(view->statusText().contains(QStringLiteral("refused the write of Current ramp")),
             qPrintable(view->statusText()));
    QVERIFY(!view->mismatchText().isEmpty());
}

void tst_DriveLimitsView::v23DriveHasNoLimits()
{
    SimRig rig(QStringLiteral("1:MF"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QVERIFY(!view->isSupported());
    const auto *note = view->findChild<QLabel *>(QStringLiteral("unsupported"));
    QVERIFY(note && note->isVisible());
    QVERIFY(note->text().contains(QStringLiteral("do not exist")));
    QVERIFY(!button(*view, "limitsRead")->isVisible());
    view->readFromDrive();
    view->writeToRam();
    QVERIFY(rig.barrier());
    QCOMPARE(rig.count(1, Command::ReadParam) + paramWrites(rig, 1), 0);
}

void tst_DriveLimitsView::tuningViewHasLimitsTab()
{
    SimRig rig(QStringLiteral("1:MF@2.35"));
    QVERIFY(rig.open());
    lk::ui::TuningView view;
    view.resize(1200, 800);
    view.setSession(&rig.session);
    view.setConnected(true);
    view.setDrive(1, rig.motor(1));
    view.show();
    QVERIFY(QTest::qWaitFor([&] { return view.limits()->readComplete(); }, kWaitMs));
    auto *tabs = view.findChild<QTabWidget *>(QStringLiteral("tuningTabs"));
    QVERIFY(tabs);
    QCOMPARE(tabs->widget(1), static_cast<QWidget *>(view.limits()));
    QCOMPARE(view.limits()->driveId(), 1);
}

void tst_DriveLimitsView::zeroIsAValueAndFirstReadIsShown()
{
    // A simulated V2.35 drive's current ramp is 0: a value the drive holds, shown as 0 in the
    // edit field (not as "unknown"), and the first complete read fills "First read".
    SimRig rig(QStringLiteral("2:MF@2.35"));
    QVERIFY(rig.open());
    QCOMPARE(ramParams(rig, 2).currentRamp, qint16(0));
    auto view = openView(rig, 2);
    QVERIFY(view && view->readComplete());
    QDoubleSpinBox *ramp = view->table()->editor(Limit::CurrentRamp);
    QCOMPARE(ramp->value(), 0.0);
    QCOMPARE(ramp->text(), QStringLiteral("0"));
    const auto first = [&](int row) {
        return view->table()
            ->findChild<QLabel *>(QStringLiteral("first_") + view->table()->field(row).key)
            ->text();
    };
    QCOMPARE(first(Limit::CurrentRamp), QStringLiteral("0"));
    QVERIFY2(first(Limit::MaxSpeed).contains(QStringLiteral("dps")),
             qPrintable(first(Limit::MaxSpeed)));
    // The first read stays the first: a later read does not replace it.
    const QString speed = first(Limit::MaxSpeed);
    rig.withDrive(2, [](lk::sim::SimDrive &d) {
        d.handle(*lk::protocol::build::writeParam(2, lk::protocol::ParamId::MaxSpeed, 720, false)
                      .request);
    });
    view->readFromDrive();
    QVERIFY(waitIdle(*view));
    QCOMPARE(heldText(*view->table(), Limit::MaxSpeed), QStringLiteral("720.00 dps"));
    QCOMPARE(first(Limit::MaxSpeed), speed);
    // Unknown again (another drive's values are not this one's): the special text is back.
    view->clearDrive();
    QCOMPARE(view->table()->editor(Limit::CurrentRamp)->text(), QStringLiteral("unknown"));
}

QTEST_MAIN(tst_DriveLimitsView)
#include "tst_drivelimitsview.moc"
