// The series chooser on a drive without a model read (CAN has none; listen-only may see
// none): series and gear ratio chosen by the user, remembered, applied again when the drive
// comes back, and the ratio kept where the Encoder view keeps it.

#include <drive/DriveSettingsStore.h>
#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/ListenOnlyControl.h>
#include <panels/BusModel.h>
#include <panels/SeriesChooser.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QPushButton>

using lk::protocol::Series;
using lk::ui::BusModel;
using lk::ui::SeriesChooser;

namespace {

lk::bus::FoundMotor found(int id, const QString &motorName = {})
{
    lk::bus::FoundMotor m;
    m.id = id;
    m.baud = 1000000;
    m.model.motorName = motorName;
    m.modelKnown = !motorName.isEmpty();
    return m;
}

/// The chooser, its control and the stores, as lkstudio wires them.
struct Rig {
    explicit Rig(const QString &ini) : settings(ini)
    {
        control = std::make_unique<lk::ui::ListenOnlyControl>(&controller, &settings, chooser, stop,
                                                              &window);
        control->setDriveStore(&store);
        window.show();
    }
    QWidget window;
    BusModel model;
    lk::ui::BusController controller{&model};
    lk::ui::AppSettings settings;
    lk::ui::MemoryDriveStore store;
    SeriesChooser *chooser = new SeriesChooser(&model, &window);
    QPushButton *stop = new QPushButton(&window);
    std::unique_ptr<lk::ui::ListenOnlyControl> control;
    QDoubleSpinBox *ratio() const
    {
        return chooser->findChild<QDoubleSpinBox *>(QStringLiteral("gearRatioSpin"));
    }
};

} // namespace

class tst_SeriesChooser : public QObject {
    Q_OBJECT
private slots:
    void noModelAsksSeriesAndGearRatio();
    void modelNameGivesTheRatio();
    void canAsksTheGenerationAndGivesTheIdentity();

private:
    QTemporaryDir m_dir;
};

void tst_SeriesChooser::noModelAsksSeriesAndGearRatio()
{
    Rig rig(m_dir.filePath(QStringLiteral("a.ini")));
    rig.model.addFound(found(3));
    rig.model.setCurrentId(3);
    QVERIFY(!rig.chooser->isHidden());
    QVERIFY(!rig.ratio()->isHidden());
    QVERIFY(!rig.model.drive(3)->gearRatio()); // unknown, not 1
    // On RS485 the generation is the model read's (or the reply lengths'): not asked.
    QVERIFY(rig.chooser->findChild<QComboBox *>(QStringLiteral("generationCombo"))->isHidden());

    rig.ratio()->setValue(36);
    emit rig.ratio()->editingFinished();
    QCOMPARE(rig.model.drive(3)->gearRatio(), std::optional<double>(36));
    // Kept where the Encoder view keeps a drive's ratio: one value, not two.
    QCOMPARE(rig.store.gearRatio(QStringLiteral("id3")), std::optional<double>(36));

    auto *series = rig.chooser->findChild<QComboBox *>(QStringLiteral("seriesCombo"));
    const int mg = series->findText(QStringLiteral("MG"));
    series->setCurrentIndex(mg);
    emit series->activated(mg);
    QCOMPARE(rig.settings.chosenSeries(rig.controller.portKey(), 3), std::optional(Series::MG));

    // The drive goes and comes back (a rescan, a reconnect): both are applied again.
    rig.model.clearDrives();
    rig.model.addFound(found(3));
    QCOMPARE(rig.model.drive(3)->gearRatio(), std::optional<double>(36));
    QVERIFY(!rig.chooser->isHidden()); // chosen here: still shown to change it
    QCOMPARE(rig.ratio()->value(), 36.0);
}

void tst_SeriesChooser::modelNameGivesTheRatio()
{
    Rig rig(m_dir.filePath(QStringLiteral("b.ini")));
    rig.store.setGearRatio(QStringLiteral("id4-MG5010E-i10"), 99); // the Encoder view's own
    rig.model.addFound(found(4, QStringLiteral("MG5010E-i10")));
    rig.model.setCurrentId(4);
    QCOMPARE(rig.model.drive(4)->gearRatio(), std::optional<double>(10)); // the name wins
    QVERIFY(rig.chooser->isHidden()); // the series came with the name
}

// On CAN, where no reply told the generation, the chooser asks it too; series, generation and
// gear ratio reach the bus together as the drive's identity (setDriveIdentity), remembered for
// the port and ID. Without a series nothing is made up: torque stays refused.
void tst_SeriesChooser::canAsksTheGenerationAndGivesTheIdentity()
{
    using lk::protocol::Generation;
    Rig rig(m_dir.filePath(QStringLiteral("c.ini")));
    rig.model.setLink(lk::protocol::Link::Can);
    lk::bus::FoundMotor m = found(5);
    m.link = lk::protocol::Link::Can;
    rig.model.addFound(m);
    rig.model.setCurrentId(5);
    QVERIFY(!rig.model.drive(5)->generation()); // no model read on CAN: not V2.3 by default
    auto *generation = rig.chooser->findChild<QComboBox *>(QStringLiteral("generationCombo"));
    QVERIFY(!rig.chooser->isHidden());
    QVERIFY(!generation->isHidden());
    QCOMPARE(generation->currentIndex(), 0); // "unknown"
    const int v236 = generation->findData(int(Generation::V2_35));
    generation->setCurrentIndex(v236);
    emit generation->activated(v236);
    lk::bus::BusSession *session = rig.controller.session();
    QCOMPARE(rig.settings.chosenGeneration(rig.controller.portKey(), 5),
             std::optional(Generation::V2_35));
    QCOMPARE(rig.model.drive(5)->generation(), std::optional(Generation::V2_35));
    QVERIFY(!session->driveIdentity(5)); // no series yet: no identity, nothing guessed
    QVERIFY(!session->series(5));

    rig.ratio()->setValue(6);
    emit rig.ratio()->editingFinished();
    auto *series = rig.chooser->findChild<QComboBox *>(QStringLiteral("seriesCombo"));
    const int mf = series->findText(QStringLiteral("MF"));
    series->setCurrentIndex(mf);
    emit series->activated(mf);
    auto identity = session->driveIdentity(5);
    QVERIFY(identity);
    QCOMPARE(identity->series, Series::MF);
    QCOMPARE(identity->generation, Generation::V2_35);
    QCOMPARE(identity->gearRatio, std::optional<double>(6));
    QVERIFY(session->knownMotors().value(5).identityChosen);

    // The drive comes back (a rescan): generation and series are applied again.
    rig.model.clearDrives();
    session->forgetMotors();
    rig.model.addFound(m);
    QCOMPARE(rig.model.drive(5)->generation(), std::optional(Generation::V2_35));
    identity = session->driveIdentity(5);
    QVERIFY(identity);
    QCOMPARE(identity->generation, Generation::V2_35);
}

QTEST_MAIN(tst_SeriesChooser)
#include "tst_serieschooser.moc"
