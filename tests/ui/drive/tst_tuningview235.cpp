#include "ParamTestHelpers.h"

#include <drive/ConfirmDialog.h>
#include <drive/DriveLimitsView.h>
#include <drive/ParameterTable.h>
#include <drive/TuningSetCan236.h>
#include <drive/TuningSetV235.h>
#include <drive/TuningView.h>
#include <sim/FaultInjector.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimTransport.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

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
using lk::ui::ParamValues;
using lk::ui::TuningView;
using V235 = lk::ui::TuningSetV235;
using Can236 = lk::ui::TuningSetCan236;

namespace {

/// A view on drive `id` of the rig, shown, with its first read done (answered or not).
std::unique_ptr<TuningView> openView(SimRig &rig, int id)
{
    auto view = std::make_unique<TuningView>();
    view->resize(1200, 800);
    QSignalSpy read(view.get(), &TuningView::parametersRead);
    view->setSession(&rig.session);
    view->setConnected(true);
    view->setDrive(id, rig.motor(id));
    view->show();
    if (!(read.wait(kWaitMs) || !read.isEmpty()) ||
        !QTest::qWaitFor([&] { return !view->isBusy() && !view->limits()->isBusy(); }, kWaitMs))
        return nullptr;
    return view;
}

void edit(TuningView &view, int row, int value)
{
    lk::drivetest::typeInto(view.table()->editor(row), QString::number(value));
}

QPushButton *button(TuningView &view, const char *name)
{
    return view.findChild<QPushButton *>(QLatin1String(name));
}

ParamValues gainsOf(const SimParams &p)
{
    ParamValues v;
    for (const SimParams::Pid &loop : {p.anglePid, p.speedPid, p.currentPid}) {
        for (quint16 g : loop)
            v << g;
    }
    return v;
}

bool waitIdle(TuningView &view)
{
    return QTest::qWaitFor([&] { return !view.isBusy() && !view.limits()->isBusy(); }, kWaitMs);
}

} // namespace

class tst_TuningView235 : public QObject {
    Q_OBJECT
private slots:
    void readShowsKpKiKd();
    void nothingWritableBeforeRead();
    void ramWriteReadsBack();
    void romWriteAsksAndSendsOnce();
    void refusedWriteNamesParameter();
    void restoreWritesFirstRead();
    void filesKeepTheirGeneration();
    void canV236IsRamOnly();
    void oldCanKeepsRamAndRom();
};

void tst_TuningView235::readShowsKpKiKd()
{
    SimRig rig(QStringLiteral("1:MS4015@2.35"));
    QVERIFY(rig.open());
    rig.withDrive(1, [](lk::sim::SimDrive &d) {
        QVERIFY(d.handle(*lk::protocol::build::writeParamPid(1, lk::protocol::ParamId::SpeedPid,
                                                             300, 40, 12, false)
                              .request));
    });
    auto view = openView(rig, 1);
    QVERIFY(view);
    QVERIFY(view->readComplete());
    QCOMPARE(view->table()->rowCount(), int(V235::kFieldCount));
    QCOMPARE(*view->table()->pending(), gainsOf(ramParams(rig, 1)));
    QCOMPARE(view->table()->pending()->at(V235::SpeedKd), 12);
    QCOMPARE(view->table()->pending()->at(V235::SpeedKp), 300); // above V2.3's 255
    QCOMPARE(heldText(*view->table(), V235::SpeedKd), QStringLiteral("12"));
    QVERIFY(view->table()->editor(V235::AngleKd)->isEnabled());
    QCOMPARE(rig.count(1, Command::ReadParam), 3 + 6); // gains, then the limits tab
    QCOMPARE(rig.count(1, Command::ReadPid) + rig.count(1, Command::ReadAccel), 0);
    const auto *note = view->findChild<QLabel *>(QStringLiteral("generationNote"));
    QVERIFY(note && note->text().contains(QStringLiteral("0x33/0x34")));
}

void tst_TuningView235::nothingWritableBeforeRead()
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
    QVERIFY2(view->statusText().contains(QStringLiteral("Could not read drive 1")),
             qPrintable(view->statusText()));
    QVERIFY(!view->table()->pending());
    QVERIFY(!view->driveValues().at(V235::AngleKp)); // unknown, not 0
    QCOMPARE(view->driveValues().at(V235::SpeedKp), std::optional<qint64>(50));
    for (int r = 0; r < view->table()->rowCount(); ++r) {
        QCOMPARE(view->table()->editor(r)->text(), QStringLiteral("unknown"));
        QVERIFY(!view->table()->editor(r)->isEnabled());
    }
    QCOMPARE(heldText(*view->table(), V235::AngleKp), QStringLiteral("unknown"));
    for (const char *name : {"writeRam", "writeRom", "undo", "load", "save"})
        QVERIFY2(!button(*view, name)->isEnabled(), name);
    int asked = 0;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &) { return ++asked > 0; });
    view->writeToRam();
    view->writeToRom();
    QVERIFY(rig.barrier());
    QCOMPARE(paramWrites(rig, 1), 0);
    QCOMPARE(asked, 0);
}

void tst_TuningView235::ramWriteReadsBack()
{
    SimRig rig(QStringLiteral("1:MF@2.35"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    const SimParams rom = romParams(rig, 1);
    const int readsBefore = rig.count(1, Command::ReadParam);
    edit(*view, V235::SpeedKd, 7);
    edit(*view, V235::IqKp, 1000);
    QVERIFY(view->table()->isChanged(V235::SpeedKd));
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QVERIFY(waitIdle(*view));
    QCOMPARE(ramParams(rig, 1).speedPid[2], quint16(7));
    QCOMPARE(ramParams(rig, 1).currentPid[0], quint16(1000));
    QCOMPARE(romParams(rig, 1), rom);                  // RAM only
    QCOMPARE(rig.count(1, Command::WriteParamRam), 3); // one per loop
    QCOMPARE(rig.count(1, Command::WriteParamRom), 0);
    QCOMPARE(rig.count(1, Command::ReadParam), readsBefore + 3); // read back
    QCOMPARE(view->driveValues().at(V235::SpeedKd), std::optional<qint64>(7));
    QVERIFY(!view->table()->anyChanged());
    QVERIFY(view->mismatchText().isEmpty());
    QVERIFY2(view->statusText().contains(QStringLiteral("read back")),
             qPrintable(view->statusText()));
    QVERIFY(view->romWarningShown()); // changed in RAM, not in ROM
}

void tst_TuningView235::romWriteAsksAndSendsOnce()
{
    SimRig rig(QStringLiteral("1:MS4015@2.35"));
    // Each ROM write goes out once: a reply late past the margin fails the write for good. The
    // full suite once stalled one past 100 ms ("did not answer" on the clean write).
    rig.minMarginMs = 400;
    rig.maxMarginMs = 800;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    edit(*view, V235::AngleKd, 5);
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
    QVERIFY(asked.first().question.contains(QStringLiteral("5")));
    QCOMPARE(paramWrites(rig, 1), 0); // declined: nothing sent
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));

    answer = true;
    rig.sim->withBus([](lk::sim::SimBus &bus) {
        // the first 0x44 reply is lost
        bus.faults().dropNextRepliesTo(quint8(Command::WriteParamRom), 1, 1);
    });
    view->writeToRom();
    QVERIFY(waitIdle(*view));
    QCOMPARE(asked.size(), 2);
    QCOMPARE(rig.count(1, Command::WriteParamRom), 3); // once per loop, the lost one not retried
    QCOMPARE(rig.count(1, Command::WriteParamRam), 0);
    QCOMPARE(romParams(rig, 1).anglePid[2], quint16(5));
    QCOMPARE(view->driveValues().at(V235::AngleKd), std::optional<qint64>(5)); // read back
    QVERIFY2(view->statusText().contains(QStringLiteral("failed")),
             qPrintable(view->statusText())); // the lost reply is reported

    view->writeToRom(); // a clean one: verified by the read-back
    QVERIFY(waitIdle(*view));
    QCOMPARE(rig.count(1, Command::WriteParamRom), 6);
    QVERIFY2(view->statusText().contains(QStringLiteral("read back with 0x40")),
             qPrintable(view->statusText()));
    QVERIFY(!view->romWarningShown());
}

void tst_TuningView235::refusedWriteNamesParameter()
{
    SimRig rig(QStringLiteral("1:MF@2.35+param-write-refused"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    const SimParams before = ramParams(rig, 1);
    edit(*view, V235::AngleKp, 123);
    view->writeToRam();
    QVERIFY(waitIdle(*view));
    QCOMPARE(ramParams(rig, 1), before);
    const QString status = view->statusText();
    QVERIFY2(status.contains(QStringLiteral("refused")) &&
                 status.contains(QStringLiteral("Angle loop Kp")) &&
                 status.contains(QStringLiteral("flag 1")),
             qPrintable(status));
    QVERIFY2(view->mismatchText().contains(QStringLiteral("Angle loop Kp: the drive holds")),
             qPrintable(view->mismatchText()));
    QVERIFY(view->table()->isChanged(V235::AngleKp)); // the edit stays
}

void tst_TuningView235::restoreWritesFirstRead()
{
    SimRig rig(QStringLiteral("1:MG@2.35"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    const ParamValues original = gainsOf(ramParams(rig, 1));
    edit(*view, V235::IqKd, 33);
    view->writeToRam();
    QVERIFY(waitIdle(*view));
    QCOMPARE(ramParams(rig, 1).currentPid[2], quint16(33));
    QList<ConfirmRequest> asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q;
        return true;
    });
    QVERIFY(button(*view, "undo")->text().startsWith(QStringLiteral("Restore values read at")));
    QTest::mouseClick(button(*view, "undo"), Qt::LeftButton);
    QVERIFY(waitIdle(*view));
    QCOMPARE(asked.size(), 1);
    QVERIFY2(asked.first().question.contains(QStringLiteral("to its RAM")) &&
                 asked.first().question.contains(QStringLiteral("(Kp/Ki/Kd)")),
             qPrintable(asked.first().question));
    QCOMPARE(gainsOf(ramParams(rig, 1)), original);
    QCOMPARE(*view->table()->pending(), original);
    QCOMPARE(rig.count(1, Command::WriteParamRom), 0); // RAM only
}

void tst_TuningView235::filesKeepTheirGeneration()
{
    SimRig rig(QStringLiteral("1:MF@2.35,2:MF"));
    QVERIFY(rig.open());
    QTemporaryDir dir;
    const QString v235 = dir.filePath(QStringLiteral("v235.json"));
    const QString v23 = dir.filePath(QStringLiteral("v23.json"));
    auto view = openView(rig, 1);
    QVERIFY(view && view->readComplete());
    QCOMPARE(view->saveParameters(v235), QString());
    QSignalSpy read(view.get(), &TuningView::parametersRead);
    view->setDrive(2, rig.motor(2));
    QVERIFY(read.wait(kWaitMs) || !read.isEmpty());
    QVERIFY(waitIdle(*view) && view->readComplete());
    QCOMPARE(view->table()->rowCount(), 7); // the V2.3 set
    QCOMPARE(view->saveParameters(v23), QString());
    const ParamValues before = *view->table()->pending();
    QString error = view->loadParameters(v235);
    QVERIFY2(error.contains(QStringLiteral("v2.35")), qPrintable(error));
    QCOMPARE(*view->table()->pending(), before);

    read.clear();
    view->setDrive(1, rig.motor(1));
    QVERIFY(read.wait(kWaitMs) || !read.isEmpty());
    QVERIFY(waitIdle(*view) && view->readComplete());
    error = view->loadParameters(v23);
    QVERIFY2(error.contains(QStringLiteral("v2.3 drive")), qPrintable(error));
    edit(*view, V235::IqKd, 9);
    QCOMPARE(view->loadParameters(v235), QString());
    QCOMPARE(view->table()->pending()->at(V235::IqKd), 0); // the file's value
    QCOMPARE(paramWrites(rig, 1), 0);                      // loading writes nothing
}

QTEST_MAIN(tst_TuningView235)
void tst_TuningView235::canV236IsRamOnly()
{
    // A V2.36 drive on CAN (the simulator's CAN front): its control parameters are read with
    // 0xC0 and written with 0xC1 to RAM only. No ROM button (absent, not greyed), a label
    // that says why, only the changed parameter written, read back, and nothing of RS485's
    // 0x40..0x44 or any ROM write ever sent.
    lk::bus::BusSession session;
    QSignalSpy done(&session, &lk::bus::BusSession::requestCompleted);
    session.setDriveIdentity({1, lk::protocol::Series::MF, lk::protocol::Generation::V2_35, {}});
    lk::transport::SimSettings settings;
    settings.spec = *lk::sim::SimBusSpec::parse(QStringLiteral("1:MF@2.35"));
    settings.link = lk::protocol::Link::Can;
    lk::bus::BusConfig config;
    config.minMarginMs = 100; // a loaded machine must never turn a late reply into silence
    config.initialMarginMs = 100;
    session.open(lk::transport::SimTransport::factory(settings), 1000000, config);
    QVERIFY(QTest::qWaitFor([&] { return session.connection().isOpen(); }, kWaitMs));
    auto view = std::make_unique<TuningView>();
    view->resize(1200, 800);
    QSignalSpy read(view.get(), &TuningView::parametersRead);
    view->setSession(&session);
    view->setLink(lk::protocol::Link::Can);
    view->setConnected(true);
    view->setDrive(1, session.knownMotors().value(1));
    view->show();
    QVERIFY(read.wait(kWaitMs) || !read.isEmpty());
    QVERIFY(waitIdle(*view));
    QVERIFY(view->isRamOnly());
    QVERIFY2(view->readComplete(), qPrintable(view->statusText()));
    QCOMPARE(view->table()->rowCount(), int(Can236::kFieldCount));
    QVERIFY(!button(*view, "writeRom")->isVisible());
    const auto *note = view->findChild<QLabel *>(QStringLiteral("ramOnlyNote"));
    QVERIFY(note && note->isVisible());
    QVERIFY(note->text().contains(
        QStringLiteral("CAN V2.36 keeps these in RAM only: they are lost at power-off.")));
    // The current ramp's unit is unknown: its row says so and shows the raw number.
    QVERIFY(view->table()->field(Can236::CurrentRamp).name.contains(QStringLiteral("unknown")));
    QVERIFY(view->table()->field(Can236::CurrentRamp).suffix.isEmpty());

    const auto commands = [&] {
        QList<Command> out;
        for (const auto &args : done)
            out << args.at(0).value<lk::bus::RequestResult>().request.command;
        return out;
    };
    QCOMPARE(commands().count(Command::ReadControlParam), 8);
    const qsizetype before = done.size();
    edit(*view, Can236::SpeedKp, 77);
    view->writeToRam();
    QVERIFY(waitIdle(*view));
    QVERIFY2(view->mismatchText().isEmpty(), qPrintable(view->mismatchText()));
    QCOMPARE(heldText(*view->table(), Can236::SpeedKp), QStringLiteral("77"));
    QCOMPARE(commands().count(Command::WriteControlParam), 1); // only the changed loop
    QVERIFY(done.size() > before);
    // ROM: refused with the reason, nothing sent.
    const qsizetype afterRam = done.size();
    view->writeToRom();
    QTest::qWait(50);
    QCOMPARE(done.size(), afterRam);
    QVERIFY(view->statusText().contains(QStringLiteral("RAM only")));
    for (Command c : commands())
        QVERIFY2(c == Command::ReadControlParam || c == Command::WriteControlParam,
                 qPrintable(lk::protocol::CommandTable::name(c)));
    // The drive holds it: an independent 0xC0 read.
    QSignalSpy one(&session, &lk::bus::BusSession::requestCompleted);
    session.send(
        *lk::protocol::build::readControlParam(1, lk::protocol::ControlParamId::SpeedPid).request);
    QVERIFY(one.wait(kWaitMs) || !one.isEmpty());
    const auto r = one.at(0).at(0).value<lk::bus::RequestResult>();
    QVERIFY(r.reply);
    QCOMPARE(std::get<lk::protocol::ControlParameter>(r.reply->payload).pid()[0], quint16(77));
    view.reset();
    session.close();
}

void tst_TuningView235::oldCanKeepsRamAndRom()
{
    // A V2.3 drive: the old CAN generation has V2.3's 0x30..0x34 with RAM and ROM: the link alone
    // takes nothing away (only a V2.36 drive on CAN is RAM only).
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    view->setLink(lk::protocol::Link::Can);
    QVERIFY(!view->isRamOnly());
    QVERIFY(view->readComplete()); // what was read stays: the set did not change
    QVERIFY(rig.count(1, Command::ReadPid) > 0);
    QVERIFY(button(*view, "writeRom")->isVisible());
    QVERIFY(!view->findChild<QLabel *>(QStringLiteral("ramOnlyNote"))->isVisible());
}

#include "tst_tuningview235.moc"
