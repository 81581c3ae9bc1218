// Renders the drive views on the built-in simulated bus to PNG files for docs/:
//   QT_QPA_PLATFORM=offscreen drive_screenshots [OUTPUT_DIR [LANGUAGE]]
// e.g. `drive_screenshots docs/zh_CN zh_CN` for the Chinese pictures.
// Not a test: it produces pictures for people to look at.
#include "DriveTestRig.h"

#include <bus/SetpointWaveform.h>
#include <drive/ConfirmDialog.h>
#include <drive/ControlModePanel.h>
#include <drive/ControlView.h>
#include <drive/DriveInfoView.h>
#include <drive/EncoderView.h>
#include <drive/LoopPlot.h>
#include <drive/ParameterTable.h>
#include <drive/SetpointPanel.h>
#include <drive/TuningSetV23.h>
#include <drive/TuningView.h>
#include <main/LanguageLoader.h>
#include <safety/SoftLimits.h>
#include <tuning/StepRunList.h>
#include <tuning/StepRunsModel.h>
#include <tuning/StepRunsView.h>
#include <tuning/StepTestPanel.h>

#include <QtCore/QDir>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>

#include <cstdio>

using lk::drivetest::SimRig;
namespace build = lk::protocol::build;

namespace {

constexpr QSize kSize(1280, 760);

bool save(QWidget &w, const QString &dir, const char *name)
{
    const QString path = QDir(dir).filePath(QLatin1String(name));
    const bool ok = w.grab().save(path);
    std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
    return ok;
}

template <typename View> void attach(View &view, SimRig &rig, int id)
{
    view.resize(kSize);
    view.setSession(&rig.session);
    view.setConnected(true);
    view.setDrive(id, rig.motor(id));
    view.show();
}

bool tuning(SimRig &rig, const QString &dir)
{
    lk::ui::TuningView view;
    attach(view, rig, 1);
    if (!QTest::qWaitFor([&] { return view.readComplete() && !view.isBusy(); }, 10000))
        return false;
    // A speed step response to look at, and an edit that differs from the drive.
    rig.session.send(*build::speed(1, 720).request);
    QTest::qWait(1200);
    rig.session.send(*build::speed(1, -360).request);
    QTest::qWait(1200);
    rig.session.send(*build::speed(1, 0).request);
    QTest::qWait(1200);
    view.table()->editor(lk::ui::TuningSetV23::SpeedKp)->setValue(65);
    view.table()->editor(lk::ui::TuningSetV23::SpeedKi)->setValue(30);
    view.plot()->setLoop(lk::ui::TunedLoop::Speed);
    view.plot()->redraw();
    QTest::qWait(200);
    return save(view, dir, "screenshot-tuning.png");
}

/// Two speed steps of drive 1, the second after doubling the speed Kp in RAM, overlaid.
bool steps(SimRig &rig, const QString &dir)
{
    lk::ui::TuningView view;
    view.setStepTestLimits([&rig](QString *) {
        return std::optional(lk::safety::SoftLimits::defaults(rig.motor(1).series));
    });
    attach(view, rig, 1);
    if (!QTest::qWaitFor([&] { return view.readComplete() && !view.isBusy(); }, 10000))
        return false;
    view.showStepResponse(true);
    lk::tuning::StepTestSpec spec = view.stepTest()->spec();
    spec.from = 0;
    spec.to = 600;
    spec.durationS = 0.8;
    view.stepTest()->setSpec(spec);
    auto runs = [&](int n) {
        return QTest::qWaitFor(
            [&] { return view.runList()->runs().size() >= n && !view.stepTest()->isRunning(); },
            20000);
    };
    if (!view.stepTest()->runTest() || !runs(1))
        return false;
    const int kp = view.driveValues().value(lk::ui::TuningSetV23::SpeedKp).value_or(50);
    view.table()->editor(lk::ui::TuningSetV23::SpeedKp)->setValue(double(kp * 3));
    view.writeToRam();
    if (!QTest::qWaitFor([&] { return !view.isBusy(); }, 10000))
        return false;
    QTest::qWait(300);
    if (!view.stepTest()->repeatLast() || !runs(2))
        return false;
    // The metrics, not the identity rows, at the top of the table.
    auto *model = view.stepRuns()->model();
    view.stepRuns()->table()->scrollTo(
        model->index(lk::ui::StepRunsModel::metricRow(lk::ui::StepMetricKind::RiseTime), 0),
        QAbstractItemView::PositionAtTop);
    QTest::qWait(300);
    return save(view, dir, "screenshot-steps.png");
}

bool control(SimRig &rig, const QString &dir)
{
    lk::ui::ControlView view;
    attach(view, rig, 1);
    // A few seconds of a sine on position for the live plot, then a refused command.
    lk::bus::SetpointWaveform::Settings sine;
    sine.waveform = lk::bus::SetpointWaveform::Waveform::Sine;
    sine.target = lk::bus::SetpointWaveform::Target::Position;
    sine.offset = rig.multiTurnDeg(1);
    sine.amplitude = 90;
    sine.periodS = 2;
    view.setpointPanel()->setSettings(sine);
    view.startGenerator(sine);
    QTest::qWait(3500);
    view.stopGenerator();
    QTest::qWait(300);
    view.modePanel()->setMode(lk::ui::ControlMode::Torque);
    view.modePanel()->setTorqueA(3);
    view.sendCommand(); // refused by the default torque limit: the view says which one
    view.plot()->setLoop(lk::ui::TunedLoop::Angle);
    view.plot()->redraw();
    QTest::qWait(300);
    return save(view, dir, "screenshot-control.png");
}

bool encoder(SimRig &rig, const QString &dir)
{
    lk::ui::EncoderView view;
    attach(view, rig, 2);
    lk::ui::ConfirmDialog::ScopedPolicy yes([](const lk::ui::ConfirmRequest &) { return true; });
    if (!QTest::qWaitFor([&] { return view.lastMultiTurnDeg().has_value(); }, 10000))
        return false;
    view.clearAngle();
    if (!QTest::qWaitFor([&] { return view.lastAngleCheck().has_value(); }, 10000))
        return false;
    QTest::qWait(500);
    return save(view, dir, "screenshot-encoder.png");
}

bool info(SimRig &rig, const QString &dir)
{
    lk::ui::DriveInfoView view;
    attach(view, rig, 2);
    view.resize(900, 520);
    bool ready = false;
    QObject::connect(&view, &lk::ui::DriveInfoView::busReportReady, [&] { ready = true; });
    view.gatherBusReport();
    if (!QTest::qWaitFor([&] { return ready; }, 10000))
        return false;
    return save(view, dir, "screenshot-driveinfo.png");
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QString dir = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QStringLiteral("docs");
    if (argc > 2)
        lk::ui::LanguageLoader::install(QString::fromLocal8Bit(argv[2]));
    QDir().mkpath(dir);
    SimRig rig;
    if (!rig.open()) {
        std::fprintf(stderr, "could not open the simulated bus\n");
        return 1;
    }
    rig.session.startPolling(lk::bus::PollPlan::standard({1, 2, 3, 4}, 50));
    bool ok = tuning(rig, dir);
    ok = steps(rig, dir) && ok;
    ok = control(rig, dir) && ok;
    ok = encoder(rig, dir) && ok;
    ok = info(rig, dir) && ok;
    return ok ? 0 : 1;
}
