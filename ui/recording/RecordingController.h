#pragma once

#include <QtCore/QObject>

class QAction;
class QMainWindow;
class QMenu;

namespace lk::ui {

class AppSettings;
class BlackBoxRecorder;
class BlackBoxTrafficFeed;
class BusController;
class LeaveGuard;
class MessageBanner;
class RecordingReplay;
class ReplayBar;
class StatisticsView;
class TelemetryStore;
class TrafficPanel;

/// lkstudio's recording features, wired to the window's pieces: the black box on every
/// connection (BlackBoxRecorder), the Traffic view fed from its ring, the banner entry that
/// says where a saved recording is, File -> "Save the last 10 minutes", and the replay of a
/// recording (File -> Open recording, `lkstudio FILE`) into the same views as live.
class RecordingController : public QObject {
    Q_OBJECT
public:
    /// The window's pieces it works with; none is owned, all outlive the controller's use.
    struct Parts {
        BusController *controller = nullptr;
        LeaveGuard *leaveGuard = nullptr;
        TelemetryStore *store = nullptr;
        TrafficPanel *traffic = nullptr;
        MessageBanner *banner = nullptr;
        QMainWindow *window = nullptr;        ///< gets the replay toolbar
        AppSettings *settings = nullptr;      ///< keeps the black box's length; none: not kept
        StatisticsView *statistics = nullptr; ///< shows a replay's figures; none: not shown
    };
    /// The banner entry of a saved (or failed) black-box recording.
    static QString entryKey() { return QStringLiteral("blackBox"); }
    /// The banner entry of the recording being replayed (or that could not be opened).
    static QString replayKey() { return QStringLiteral("replay"); }
    static QString exportKey() { return QStringLiteral("recordingExport"); }

    RecordingController(const Parts &parts, QObject *parent = nullptr);

    BlackBoxRecorder *blackBox() const { return m_recorder; }
    BlackBoxTrafficFeed *trafficFeed() const { return m_feed; }
    RecordingReplay *replay() const { return m_replay; }
    ReplayBar *replayBar() const { return m_bar; }
    /// Add the recording actions to the File menu.
    void addFileActions(QMenu *file);
    QAction *saveAction() const { return m_save; }
    QAction *lengthAction() const { return m_length; }

public slots:
    /// File -> Save the last 10 minutes.
    void saveNow();
    /// The black box keeps `minutes` from now on, and the settings keep it. A value outside
    /// AppSettings' 1..60 is refused: false, and the banner names the setting.
    bool setBlackBoxMinutes(int minutes);
    /// File -> Black box length: asks for the minutes.
    void chooseBlackBoxMinutes();
    /// Close the bus (what was set moving is stopped first, or the user keeps it: then
    /// nothing happens) and play `path` into the views. False when it was not opened; the
    /// banner says why (the reader's message names the offset of damage).
    bool openRecording(const QString &path);
    void openRecordingWithDialog();
    void closeRecording();
    /// Writes the CAN recording `recordingPath` (a saved black box too) as a candump -L log
    /// at `logPath` (recording::CandumpLog), whole or not at all. False, with the banner
    /// saying why, for a recording not made on CAN or a file that cannot be read or written.
    bool exportCandump(const QString &recordingPath, const QString &logPath);
    /// File -> Export recording as candump log: asks for the recording and the log.
    void exportCandumpWithDialog();

private:
    /// The cause a save names (BlackBoxTriggers' reason names, or kOnRequest), worded.
    static QString causeText(const QString &why);
    void showSaved(const QString &why, const QString &path);
    void showSaveFailed(const QString &why, const QString &error);
    void wireReplay();
    void showReplaying();

    Parts m_parts;
    BlackBoxRecorder *m_recorder;
    BlackBoxTrafficFeed *m_feed;
    RecordingReplay *m_replay;
    ReplayBar *m_bar;
    QAction *m_save = nullptr;
    QAction *m_length = nullptr;
};

} // namespace lk::ui
