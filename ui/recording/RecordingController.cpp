#include "RecordingController.h"

#include "BlackBoxRecorder.h"
#include "BlackBoxTrafficFeed.h"

#include "RecordingReplay.h"
#include "ReplayBar.h"

#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/LeaveGuard.h>
#include <panels/BusModel.h>
#include <panels/MessageBanner.h>
#include <panels/StatisticsView.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>
#include <plot/TelemetryStore.h>

#include <recording/CandumpLog.h>
#include <recording/RecordingReader.h>

#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QSaveFile>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QInputDialog>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QMenu>

namespace lk::ui {

namespace {
const QString kOnRequest = QStringLiteral("on request");

recording::RecordingHeader headerFor(const ConnectionChoice &choice)
{
    recording::RecordingHeader h;
    if (choice.link() == protocol::Link::Can) {
        // CAN records are what is recorded (a CAN interface or the simulator on CAN): the
        // file says so, and readers parse it as CAN (recording::linkOf).
        h.linkKind = recording::LinkKind::Can;
        h.linkDescription =
            QStringLiteral("%1:%2 @ %3")
                .arg(choice.isSimulator() ? QStringLiteral("simulator") : choice.canPlugin,
                     choice.isSimulator() ? QStringLiteral("can0") : choice.canInterface)
                .arg(choice.bitRate);
        h.baud = choice.bitRate;
        return h;
    }
    h.linkKind =
        choice.isSimulator() ? recording::LinkKind::Simulated : recording::LinkKind::Serial;
    h.linkDescription = QStringLiteral("%1 @ %2")
                            .arg(choice.isSimulator() ? QStringLiteral("simulator") : choice.port)
                            .arg(choice.baud);
    h.baud = choice.baud;
    return h;
}
} // namespace

RecordingController::RecordingController(const Parts &parts, QObject *parent)
    : QObject(parent), m_parts(parts), m_recorder(new BlackBoxRecorder(this)),
      m_feed(new BlackBoxTrafficFeed(m_recorder, parts.traffic, this)),
      m_replay(new RecordingReplay(this)), m_bar(new ReplayBar(m_replay, parts.window))
{
    parts.controller->addFactoryWrapper(
        [this](bus::TransportFactory inner, const ConnectionChoice &choice) {
            closeRecording(); // a live bus replaces the replay
            return m_recorder->wrap(std::move(inner), headerFor(choice));
        });
    if (parts.settings)
        m_recorder->setWindowMinutes(parts.settings->blackBoxMinutes());
    m_recorder->attach(parts.controller->session());
    connect(m_recorder, &BlackBoxRecorder::saved, this, &RecordingController::showSaved);
    connect(m_recorder, &BlackBoxRecorder::saveFailed, this, &RecordingController::showSaveFailed);
    parts.window->addToolBar(Qt::BottomToolBarArea, m_bar);
    m_bar->hide();
    wireReplay();
}

void RecordingController::wireReplay()
{
    BusModel *model = m_parts.controller->model();
    const auto addDrive = [this, model](int id, std::optional<protocol::Series> series) {
        if (model->drive(id))
            return;
        bus::FoundMotor found;
        found.id = id;
        found.baud = m_replay->header().baud;
        // On CAN no model is read: an empty one would claim the V2.3 generation over what
        // the recording's context or a reply's ID says (applyKnownMotors sets that next).
        found.link = m_replay->link();
        found.series = series;
        model->addFound(found);
    };
    connect(m_replay, &RecordingReplay::drivesChanged, this,
            [addDrive](const recording::ContextSnapshot &drives) {
                for (const recording::DriveContext &d : drives)
                    addDrive(d.id, d.series);
            });
    connect(m_replay, &RecordingReplay::driveSeen, this,
            [addDrive](int id) { addDrive(id, std::nullopt); });
    // What the drives are and the traffic's figures, as a listening session gives them.
    connect(m_replay, &RecordingReplay::knownMotorsChanged, this,
            [addDrive, model](const bus::KnownMotors &motors) {
                for (const bus::KnownMotor &m : motors)
                    addDrive(m.id, m.series); // the model shows no drive it does not list
                model->applyKnownMotors(motors);
            });
    connect(m_replay, &RecordingReplay::listenStatisticsUpdated, model,
            &BusModel::setListenStatistics);
    connect(m_replay, &RecordingReplay::telemetryReceived, model, &BusModel::applyTelemetry);
    connect(m_replay, &RecordingReplay::telemetryReceived, m_parts.store, &TelemetryStore::append);
    connect(m_replay, &RecordingReplay::trafficCaptured, m_parts.traffic,
            &TrafficPanel::appendTraffic);
    // Load all hands on only the rows the Traffic view can keep, and counts the others.
    m_replay->setTrafficRowsKept(m_parts.traffic->trafficModel()->capacity());
    connect(m_replay, &RecordingReplay::trafficDropped, m_parts.traffic,
            &TrafficPanel::countDroppedTraffic);
    connect(m_bar, &ReplayBar::closeRequested, this, &RecordingController::closeRecording);
}

void RecordingController::addFileActions(QMenu *file)
{
    m_save = file->addAction(tr("Save the last %n minute(s)", nullptr, m_recorder->windowMinutes()),
                             this, &RecordingController::saveNow);
    m_save->setObjectName(QStringLiteral("saveBlackBox"));
    m_save->setToolTip(tr("Write what the black box holds to %1").arg(m_recorder->folder()));
    m_length = file->addAction(tr("Black box &length\u2026"), this,
                               &RecordingController::chooseBlackBoxMinutes);
    m_length->setObjectName(QStringLiteral("blackBoxLength"));
    QAction *open = file->addAction(tr("&Open recording\u2026"), this,
                                    &RecordingController::openRecordingWithDialog);
    open->setObjectName(QStringLiteral("openRecording"));
    QAction *candump = file->addAction(tr("Export recording as &candump log\u2026"), this,
                                       &RecordingController::exportCandumpWithDialog);
    candump->setObjectName(QStringLiteral("exportCandump"));
    candump->setToolTip(tr("Write a recording made on CAN as a candump -L log, which can-utils, "
                           "python-can and SavvyCAN read"));
}

void RecordingController::exportCandumpWithDialog()
{
    const QString in = QFileDialog::getOpenFileName(
        m_parts.window, tr("Export recording as candump log"), m_recorder->folder(),
        tr("LK Servo Studio recordings (*.lkrec);;All files (*)"));
    if (in.isEmpty())
        return;
    const QString suggested =
        QFileInfo(in).dir().filePath(QFileInfo(in).completeBaseName() + QStringLiteral(".log"));
    const QString out =
        QFileDialog::getSaveFileName(m_parts.window, tr("Export recording as candump log"),
                                     suggested, tr("candump logs (*.log);;All files (*)"));
    if (!out.isEmpty())
        exportCandump(in, out);
}

bool RecordingController::exportCandump(const QString &recordingPath, const QString &logPath)
{
    const auto fail = [this](const QString &text) {
        m_parts.banner->setEntry(exportKey(), MessageBanner::Level::Error, text);
        return false;
    };
    recording::RecordingReader reader;
    if (!reader.open(recordingPath))
        return fail(
            tr("Cannot export %1: %2")
                .arg(recordingPath.toHtmlEscaped(), reader.error().message.toHtmlEscaped()));
    if (recording::linkOf(reader.header()) != protocol::Link::Can)
        return fail(tr("%1 was recorded on %2, not on CAN: a candump log holds CAN frames only.")
                        .arg(QFileInfo(recordingPath).fileName().toHtmlEscaped(),
                             reader.header().linkDescription.toHtmlEscaped()));
    QSaveFile file(logPath);
    if (!file.open(QIODevice::WriteOnly))
        return fail(tr("Cannot write %1: %2")
                        .arg(logPath.toHtmlEscaped(), file.errorString().toHtmlEscaped()));
    const qint64 frames = recording::CandumpLog::write(reader, file);
    if (!file.commit())
        return fail(tr("Cannot write %1: %2")
                        .arg(logPath.toHtmlEscaped(), file.errorString().toHtmlEscaped()));
    QString text = tr("%n frame(s) written to %1 as a candump log.", nullptr, int(frames))
                       .arg(logPath.toHtmlEscaped());
    if (reader.error().isError())
        text += QLatin1Char(' ') + tr("The recording is damaged: it was exported up to the "
                                      "damage (%1).")
                                       .arg(reader.error().message.toHtmlEscaped());
    m_parts.banner->setEntry(exportKey(),
                             reader.error().isError() ? MessageBanner::Level::Warning
                                                      : MessageBanner::Level::Info,
                             text);
    return true;
}

void RecordingController::openRecordingWithDialog()
{
    const QString path =
        QFileDialog::getOpenFileName(m_parts.window, tr("Open recording"), m_recorder->folder(),
                                     tr("LK Servo Studio recordings (*.lkrec);;All files (*)"));
    if (!path.isEmpty())
        openRecording(path);
}

bool RecordingController::openRecording(const QString &path)
{
    if (m_parts.controller->session()->isRunning()) {
        if (!m_parts.leaveGuard->prepare(LeaveGuard::Leaving::Disconnect))
            return false;
        m_parts.controller->disconnectBus();
    }
    closeRecording();
    m_feed->setSuspended(true); // the views show the recording, not the last bus's ring
    m_parts.store->clear();
    m_parts.controller->model()->clearDrives();
    m_parts.traffic->showTraffic({});
    QString error;
    BusModel *model = m_parts.controller->model();
    model->setListenStatistics({}); // the last link's figures are not the recording's
    if (!m_replay->open(path, recording::ReplayTransport::Options{}, &error)) {
        m_feed->setSuspended(false);
        m_parts.banner->setEntry(replayKey(), MessageBanner::Level::Error,
                                 tr("Cannot open the recording %1: %2")
                                     .arg(path.toHtmlEscaped(), error.toHtmlEscaped()));
        return false;
    }
    model->setLink(recording::linkOf(m_replay->header()));
    if (m_parts.statistics)
        m_parts.statistics->setReplaying(true);
    m_bar->refresh();
    showReplaying();
    return true;
}

void RecordingController::showReplaying()
{
    const recording::RecordingHeader &h = m_replay->header();
    QString text = tr("Replaying %1: %2, recorded %3. Nothing is sent while a recording plays.")
                       .arg(QFileInfo(m_replay->path()).fileName().toHtmlEscaped(),
                            h.linkDescription.toHtmlEscaped(),
                            QDateTime::fromMSecsSinceEpoch(h.wallClockStartMs)
                                .toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
    const recording::RecordingError damage = m_replay->damage();
    if (damage.isError())
        text += QLatin1Char(' ') +
                tr("It plays up to the damage: %1").arg(damage.message.toHtmlEscaped());
    m_parts.banner->setEntry(
        replayKey(), damage.isError() ? MessageBanner::Level::Warning : MessageBanner::Level::Info,
        text);
}

void RecordingController::closeRecording()
{
    if (!m_replay->isOpen())
        return;
    m_replay->close();
    if (m_parts.statistics)
        m_parts.statistics->setReplaying(false);
    m_parts.controller->model()->setListenStatistics({});
    m_bar->refresh();
    m_parts.banner->clearEntry(replayKey());
    m_feed->setSuspended(false);
}

void RecordingController::saveNow()
{
    m_recorder->save(kOnRequest);
}

void RecordingController::chooseBlackBoxMinutes()
{
    bool ok = false;
    const int minutes = QInputDialog::getInt(
        m_parts.window, tr("Black box length"),
        tr("Minutes of the link the black box keeps (it also keeps at most 128 MB):"),
        m_recorder->windowMinutes(), AppSettings::kMinBlackBoxMinutes,
        AppSettings::kMaxBlackBoxMinutes, 1, &ok);
    if (ok)
        setBlackBoxMinutes(minutes);
}

bool RecordingController::setBlackBoxMinutes(int minutes)
{
    if (minutes < AppSettings::kMinBlackBoxMinutes || minutes > AppSettings::kMaxBlackBoxMinutes ||
        (m_parts.settings && !m_parts.settings->setBlackBoxMinutes(minutes))) {
        m_parts.banner->setEntry(entryKey(), MessageBanner::Level::Warning,
                                 tr("The black box length (recording/blackBoxMinutes) must be "
                                    "%1..%2 minutes, not %3: it stays %4.")
                                     .arg(AppSettings::kMinBlackBoxMinutes)
                                     .arg(AppSettings::kMaxBlackBoxMinutes)
                                     .arg(minutes)
                                     .arg(m_recorder->windowMinutes()));
        return false;
    }
    m_recorder->setWindowMinutes(minutes);
    if (m_save)
        m_save->setText(tr("Save the last %n minute(s)", nullptr, minutes));
    return true;
}

QString RecordingController::causeText(const QString &why)
{
    if (why == QLatin1String("emergency stop"))
        return tr("the emergency stop");
    if (why == QLatin1String("fault flag"))
        return tr("a new drive fault flag");
    if (why == QLatin1String("link lost"))
        return tr("the link loss");
    if (why == QLatin1String("timeout burst"))
        return tr("a burst of timeouts");
    return tr("your request");
}

void RecordingController::showSaved(const QString &why, const QString &path)
{
    m_parts.banner->setEntry(
        entryKey(), MessageBanner::Level::Info,
        tr("Black box saved after %1: the last %n minute(s) of the link are in "
           "%2",
           nullptr, m_recorder->windowMinutes())
            .arg(causeText(why).toHtmlEscaped(), path.toHtmlEscaped()));
}

void RecordingController::showSaveFailed(const QString &why, const QString &error)
{
    m_parts.banner->setEntry(entryKey(), MessageBanner::Level::Warning,
                             tr("The black box could not be saved after %1: %2")
                                 .arg(causeText(why).toHtmlEscaped(), error.toHtmlEscaped()));
}

} // namespace lk::ui
