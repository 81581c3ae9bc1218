// Opening and plotting a one-hour recording in lkstudio's own window, as a user does with
// File -> Open recording and "Load all": bench_recording writes the hour (4 drives at 1 Mbaud,
// full rate: the bus limit of its mix), then this bench builds the MainWindow (1400x900,
// offscreen), shows the Plots view with every signal of every drive, opens the file, loads it
// all and draws the window once. The clock runs from the open to the drawn window; the
// process's peak RSS is read after it.
//
// Prints one JSON line:
//   replay_minutes         the recording's length
//   replay_open_plot_s     open, load all and draw (the issue asks <= 5 s)
//   replay_open_s, replay_load_all_s, replay_draw_s   its three parts: the open (the file's
//                          index read, every block's CRC checked), Load all until finished,
//                          the window drawn
//   replay_samples         telemetry samples the replay gave the views
//   replay_peak_rss_mb     the process's peak resident set (the issue asks <= 1 GB)
//
// Usage: bench_replay_gui [--minutes M] (default 60) [--file FILE] (open FILE, written before
// by bench_recording --keep, instead of writing one: for profiling the open alone)

#include "../bus/BenchUtil.h"

#include <main/AppSettings.h>
#include <main/MainWindow.h>
#include <panels/BusModel.h>
#include <plot/PlotPanel.h>
#include <recording/BlackBoxRecorder.h>
#include <recording/RecordingController.h>
#include <recording/RecordingReplay.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtWidgets/QApplication>

#include <sys/resource.h>

#include <cstdio>

using namespace lk;

namespace {

double peakRssMb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

/// bench_recording writes `minutes` of the 4-drive bus to `file`.
bool writeRecording(double minutes, const QString &dir, const QString &file)
{
    QProcess writer;
    writer.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    writer.setStandardOutputFile(QProcess::nullDevice());
    writer.start(QStringLiteral(BENCH_RECORDING_PATH),
                 {QStringLiteral("--minutes"), QString::number(minutes), QStringLiteral("--dir"),
                  dir, QStringLiteral("--keep"), file});
    if (!writer.waitForFinished(600000) || writer.exitCode() != 0 || !QFile::exists(file)) {
        std::fprintf(stderr, "bench_replay_gui: bench_recording did not write %s\n",
                     qPrintable(file));
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    double minutes = 60;
    QString given;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--minutes"))
            minutes = args[i + 1].toDouble();
        else if (args[i] == QLatin1String("--file"))
            given = args[i + 1];
    }
    QTemporaryDir dir;
    const QString file = given.isEmpty() ? dir.filePath(QStringLiteral("hour.lkrec")) : given;
    if (given.isEmpty() && !writeRecording(minutes, dir.path(), file))
        return 1;

    ui::AppSettings settings(dir.filePath(QStringLiteral("lkstudio.ini")));
    ui::MainWindow window(&settings);
    window.recording()->blackBox()->setFolder(dir.filePath(QStringLiteral("recordings")));
    window.resize(1400, 900);
    for (const auto channel : ui::PlotPanel::pickableChannels())
        window.plots()->setChannelVisible(channel, true);
    ui::BusModel *model = window.busModel();
    QObject::connect(model, &ui::BusModel::drivesChanged, &window,
                     [model] { model->setSelectedIds(model->ids()); });
    window.showView(QStringLiteral("plots"));
    window.show();
    QCoreApplication::processEvents();

    ui::RecordingReplay *replay = window.recording()->replay();
    qint64 samples = 0;
    QObject::connect(replay, &ui::RecordingReplay::telemetryReceived, &window,
                     [&samples](const bus::TelemetryBatch &b) { samples += b.size(); });
    // The event loop waits as lkstudio's does (a loop of processEvents would spin while the
    // load's worker decodes, and count that spinning as the window's cost).
    bool finished = false;
    QEventLoop loop;
    QObject::connect(replay, &ui::RecordingReplay::finished, &loop, [&finished, &loop] {
        finished = true;
        loop.quit();
    });
    QTimer::singleShot(600000, &loop, &QEventLoop::quit);
    QElapsedTimer clock;
    clock.start();
    if (!window.recording()->openRecording(file)) {
        std::fprintf(stderr, "bench_replay_gui: the window did not open %s\n", qPrintable(file));
        return 1;
    }
    const double openS = clock.nsecsElapsed() * 1e-9;
    replay->loadAll();
    if (!finished)
        loop.exec();
    const double loadedS = clock.nsecsElapsed() * 1e-9;
    (void)window.grab(); // the window drawn with everything loaded
    const double seconds = clock.nsecsElapsed() * 1e-9;

    bench::JsonLine json;
    json.add(QStringLiteral("replay_minutes"), minutes, 1);
    json.add(QStringLiteral("replay_open_plot_s"), finished ? seconds : -1, 2);
    json.add(QStringLiteral("replay_open_s"), openS, 2);
    json.add(QStringLiteral("replay_load_all_s"), loadedS - openS, 2);
    json.add(QStringLiteral("replay_draw_s"), seconds - loadedS, 2);
    json.addInt(QStringLiteral("replay_samples"), samples);
    json.add(QStringLiteral("replay_peak_rss_mb"), peakRssMb(), 1);
    json.print();
    return finished ? 0 : 1;
}
