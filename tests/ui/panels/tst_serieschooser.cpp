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

QTEST_MAIN(tst_SeriesChooser)
#include "tst_serieschooser.moc"
