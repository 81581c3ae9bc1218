#include "FleetRig.h"

#include <drive/ConfirmDialog.h>
#include <fleet/BackupFile.h>
#include <fleet/FleetGrid.h>
#include <fleet/FleetWriteDialog.h>
#include <fleet/ParametersView.h>
#include <sim/SimParamsSeed.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableWidget>

using namespace lk;
using fleettest::FleetRig;
using fleettest::kWaitMs;
using protocol::Command;

namespace {

const QString kSpec = QStringLiteral("1:MF,2:MF,3:MS4015@2.35");

struct ViewRig {
    explicit ViewRig(const QString &spec = kSpec, protocol::Link link = protocol::Link::Rs485)
        : rig(spec, link)
    {
    }
    FleetRig rig;
    ui::ParametersView view;

    bool open(const QVector<int> &ids)
    {
        if (!rig.open())
            return false;
        int seeded = 0;
        rig.withBus([&](sim::SimBus &bus) { seeded = sim::SimParamsSeed::apply(bus, 9); });
        view.setSession(&rig.session);
        view.setConnected(true);
        view.setDrives(ids);
        view.resize(900, 600);
        view.show();
        return seeded == 3;
    }
    bool readAll()
    {
        QPushButton *read = view.findChild<QPushButton *>(QStringLiteral("readAll"));
        if (!read || !read->isEnabled())
            return false;
        read->click();
        return QTest::qWaitFor(
            [this] {
                return view.findChild<QPushButton *>(QStringLiteral("readAll"))->isEnabled();
            },
            kWaitMs);
    }
    /// The cell of `key` for the drive in column `column`.
    QTableWidgetItem *cell(const QString &key, int column)
    {
        QTableWidget *t = view.table();
        for (int r = 0; r < t->rowCount(); ++r) {
            if (t->verticalHeaderItem(r)->text() == key)
                return t->item(r, column);
        }
        return nullptr;
    }
    int visibleRows()
    {
        int n = 0;
        for (int r = 0; r < view.table()->rowCount(); ++r)
            n += view.table()->isRowHidden(r) ? 0 : 1;
        return n;
    }
};

bool waitPrepared(ui::FleetWriteDialog *d)
{
    return d && QTest::qWaitFor([d] { return d->prepared(); }, kWaitMs);
}

} // namespace

class tst_ParametersView : public QObject {
    Q_OBJECT
private slots:
    void readAllShowsDrivesAndUnknown();
    void differingCellsAreMarkedAndFiltered();
    void cancelStopsTheRead();
    void cloneShowsTheDiffBeforeWriting();
    void romAsksFirstAndSendsNothingWhenDeclined();
    void restoreRefusesADamagedFile();
    void restoreFollowsTheIdMap();
    void canDrivesAreDeclaredAndV236IsRamOnly();
};

void tst_ParametersView::readAllShowsDrivesAndUnknown()
{
    ViewRig v;
    QVERIFY(v.open({1, 2, 3, 7})); // 7 is not on the bus
    QVERIFY(v.readAll());
    QTableWidget *t = v.view.table();
    QCOMPARE(t->columnCount(), 4);
    QVERIFY(t->horizontalHeaderItem(0)->text().contains(QStringLiteral("MF4015")));
    QVERIFY(t->horizontalHeaderItem(2)->text().contains(QStringLiteral("v2.35")));
    // V2.3 drives have no Kd: unknown, never 0; drive 7 was not read at all.
    QCOMPARE(v.cell(QStringLiteral("angle_kd"), 0)->text(), QStringLiteral("unknown"));
    QCOMPARE(v.cell(QStringLiteral("angle_kp"), 3)->text(), QStringLiteral("unknown"));
    protocol::PidGains pid;
    v.rig.withDrive(2, [&](sim::SimDrive &d) { pid = d.ramPid(); });
    QCOMPARE(v.cell(QStringLiteral("speed_ki"), 1)->text(), QString::number(pid.speedKi));
    QCOMPARE(v.view.findChild<QProgressBar *>(QStringLiteral("readProgress"))->value(), 4);
}

void tst_ParametersView::differingCellsAreMarkedAndFiltered()
{
    ViewRig v;
    QVERIFY(v.open({1, 2}));
    QVERIFY(v.readAll());
    // The seeded drives differ: drive 2's gains are marked against drive 1.
    QVERIFY(v.cell(QStringLiteral("iq_kp"), 1)->data(ui::FleetGrid::kDiffersRole).toBool());
    QVERIFY(!v.cell(QStringLiteral("iq_kp"), 0)->data(ui::FleetGrid::kDiffersRole).toBool());
    // Make drive 2 equal to 1 in RAM (clone), read again: only the encoder offset differs.
    ui::FleetWriteDialog *d = v.view.cloneReference();
    QVERIFY(waitPrepared(d));
    d->findChild<QPushButton *>(QStringLiteral("writeRam"))->click();
    QVERIFY(QTest::qWaitFor([d] { return d->finished(); }, kWaitMs));
    d->close();
    QVERIFY(v.readAll());
    v.view.findChild<QCheckBox *>(QStringLiteral("onlyDiffering"))->setChecked(true);
    QCOMPARE(v.visibleRows(), 1);
    QVERIFY(!v.view.table()->isRowHidden(v.cell(QStringLiteral("encoder_offset"), 1)->row()));
    v.view.findChild<QCheckBox *>(QStringLiteral("onlyDiffering"))->setChecked(false);
    QCOMPARE(v.visibleRows(), v.view.table()->rowCount());
}

void tst_ParametersView::cancelStopsTheRead()
{
    ViewRig v;
    QVERIFY(v.open({1, 2, 3}));
    connect(v.view.findChild<QProgressBar *>(QStringLiteral("readProgress")),
            &QProgressBar::valueChanged, &v.view, [&v](int value) {
                if (value == 1)
                    v.view.findChild<QPushButton *>(QStringLiteral("cancelRead"))->click();
            });
    QVERIFY(v.readAll());
    QCOMPARE(v.view.snapshots().size(), 1);
    QCOMPARE(v.rig.count(2, Command::ReadModel), 0);
    QVERIFY(v.view.findChild<QLabel *>(QStringLiteral("status"))->text().contains("Cancelled"));
}

void tst_ParametersView::cloneShowsTheDiffBeforeWriting()
{
    ViewRig v;
    QVERIFY(v.open({1, 2, 3}));
    QVERIFY(v.readAll());
    ui::FleetWriteDialog *d = v.view.cloneReference();
    QVERIFY(waitPrepared(d));
    // The diff is shown and nothing has been written yet.
    const QString text = d->text();
    QVERIFY2(text.contains(QStringLiteral("Drive 2 from drive 1")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("speed_kp")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("refused")), qPrintable(text)); // 3 is V2.35
    QCOMPARE(v.rig.count(2, Command::WritePidRam), 0);
    QVERIFY(QFile::exists(d->undoPath()));
    d->findChild<QPushButton *>(QStringLiteral("writeRam"))->click();
    QVERIFY(QTest::qWaitFor([d] { return d->finished(); }, kWaitMs));
    QCOMPARE(v.rig.count(2, Command::WritePidRam), 1);
    QCOMPARE(v.rig.count(3, Command::WriteParamRam), 0);
    QCOMPARE(fleet::DriveReport::outcomeName(d->restore().reports().at(0).outcome), "verified");
    QCOMPARE(fleet::DriveReport::outcomeName(d->restore().reports().at(1).outcome), "refused");
    protocol::PidGains one, two;
    v.rig.withDrive(1, [&](sim::SimDrive &s) { one = s.ramPid(); });
    v.rig.withDrive(2, [&](sim::SimDrive &s) { two = s.ramPid(); });
    QVERIFY(one == two);
}

void tst_ParametersView::romAsksFirstAndSendsNothingWhenDeclined()
{
    ViewRig v;
    QVERIFY(v.open({1, 2}));
    QVERIFY(v.readAll());
    ui::FleetWriteDialog *d = v.view.cloneReference();
    QVERIFY(waitPrepared(d));
    QStringList asked;
    ui::ConfirmDialog::ScopedPolicy no([&asked](const ui::ConfirmRequest &q) {
        asked << q.key;
        return false;
    });
    d->findChild<QPushButton *>(QStringLiteral("writeRom"))->click();
    QCOMPARE(asked, QStringList{QStringLiteral("fleet_rom")});
    QVERIFY(d->text().contains(QStringLiteral("nothing was sent")));
    QVERIFY(v.rig.barrier());
    QCOMPARE(v.rig.count(2, Command::WritePidRam), 0);
    QCOMPARE(v.rig.count(2, Command::WritePidRom), 0);
}

void tst_ParametersView::restoreRefusesADamagedFile()
{
    ViewRig v;
    QVERIFY(v.open({1, 2}));
    QVERIFY(v.readAll());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bus.json"));
    QCOMPARE(v.view.backupTo(path), QString());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadWrite));
    const QByteArray bytes = f.readAll();
    f.resize(bytes.size() / 2);
    f.close();
    QVERIFY(!v.view.restoreFrom(path));
    QVERIFY(
        v.view.findChild<QLabel *>(QStringLiteral("status"))->text().contains("not valid JSON"));
    QCOMPARE(v.rig.count(1, Command::WritePidRam) + v.rig.count(2, Command::WritePidRam), 0);
}

void tst_ParametersView::restoreFollowsTheIdMap()
{
    ViewRig v;
    QVERIFY(v.open({1, 2}));
    QVERIFY(v.readAll());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bus.json"));
    QCOMPARE(v.view.backupTo(path), QString());
    auto *map = v.view.findChild<QLineEdit *>(QStringLiteral("idMap"));
    map->setText(QStringLiteral("1:x"));
    QVERIFY(!v.view.restoreFrom(path)); // refused, naming the entry
    QVERIFY(v.view.findChild<QLabel *>(QStringLiteral("status"))->text().contains("1:x"));
    map->setText(QStringLiteral("1:2")); // drive 1 replaced by drive 2
    ui::FleetWriteDialog *d = v.view.restoreFrom(path);
    QVERIFY(waitPrepared(d));
    QVERIFY2(d->text().contains(QStringLiteral("Drive 2 from drive 1")), qPrintable(d->text()));
    QCOMPARE(d->restore().plans().size(), 1);
    d->findChild<QPushButton *>(QStringLiteral("writeRam"))->click();
    QVERIFY(QTest::qWaitFor([d] { return d->finished(); }, kWaitMs));
    QCOMPARE(v.rig.count(1, Command::WritePidRam), 0);
    protocol::PidGains one, two;
    v.rig.withDrive(1, [&](sim::SimDrive &s) { one = s.ramPid(); });
    v.rig.withDrive(2, [&](sim::SimDrive &s) { two = s.ramPid(); });
    QVERIFY(one == two);
}

void tst_ParametersView::canDrivesAreDeclaredAndV236IsRamOnly()
{
    // On CAN (no model read) each drive is named by the series the user declared and its CAN
    // generation. Cloning drive 2 (V2.36 MF) offers RAM only: its twin 3 has no ROM write for
    // these parameters (0xC1), the old CAN MG 1 is refused (another series and generation).
    using protocol::Generation;
    using protocol::Series;
    ViewRig v(QStringLiteral("1:MG,2:MF@2.35,3:MF@2.35"), protocol::Link::Can);
    v.rig.session.setDriveIdentity({1, Series::MG, Generation::V2_3, std::nullopt});
    v.rig.session.setDriveIdentity({2, Series::MF, Generation::V2_35, std::nullopt});
    v.rig.session.setDriveIdentity({3, Series::MF, Generation::V2_35, std::nullopt});
    QVERIFY(v.open({2, 3, 1}));
    QVERIFY(v.readAll());
    QTableWidget *t = v.view.table();
    QCOMPARE(t->columnCount(), 3);
    const QString two = t->horizontalHeaderItem(0)->text();
    const QString one = t->horizontalHeaderItem(2)->text();
    QVERIFY2(two.contains(QStringLiteral("MF (declared)")) &&
                 two.contains(QStringLiteral("CAN V2.36")),
             qPrintable(two));
    QVERIFY2(one.contains(QStringLiteral("MG (declared)")) &&
                 one.contains(QStringLiteral("CAN (old)")),
             qPrintable(one));
    sim::SimParams params;
    v.rig.withDrive(2, [&](sim::SimDrive &d) { params = d.ramParams(); });
    QCOMPARE(v.cell(QStringLiteral("speed_kp"), 0)->text(), QString::number(params.speedPid[0]));

    ui::FleetWriteDialog *d = v.view.cloneReference();
    QVERIFY(waitPrepared(d));
    const QString text = d->text();
    QVERIFY2(text.contains(QStringLiteral("RAM only")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Drive 1 from drive 2: refused")), qPrintable(text));
    auto *rom = d->findChild<QPushButton *>(QStringLiteral("writeRom"));
    QVERIFY(!rom->isEnabled());
    QVERIFY2(rom->toolTip().contains(QStringLiteral("RAM only")), qPrintable(rom->toolTip()));
    d->findChild<QPushButton *>(QStringLiteral("writeRam"))->click();
    QVERIFY(QTest::qWaitFor([d] { return d->finished(); }, kWaitMs));
    QCOMPARE(fleet::DriveReport::outcomeName(d->restore().reports().at(0).outcome), "verified");
    QCOMPARE(fleet::DriveReport::outcomeName(d->restore().reports().at(1).outcome), "refused");
    sim::SimParams three;
    v.rig.withDrive(3, [&](sim::SimDrive &s) { three = s.ramParams(); });
    QVERIFY(three.speedPid == params.speedPid);
    QVERIFY(v.rig.barrier(1));
    QVERIFY(v.rig.count(3, Command::WriteControlParam) >= 1);
    QCOMPARE(v.rig.count(1, Command::WritePidRam), 0);
    QCOMPARE(v.rig.count(1, Command::WritePidRom), 0);
}

QTEST_MAIN(tst_ParametersView)
#include "tst_parametersview.moc"
