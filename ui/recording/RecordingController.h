#pragma once

#include <QtCore/QObject>

class QAction;
class QMenu;

namespace lk::ui {

class BlackBoxRecorder;
class BlackBoxTrafficFeed;
class BusController;
class MessageBanner;
class TrafficPanel;

/// lkstudio's recording features, wired to the window's pieces: the black box on every
/// connection (BlackBoxRecorder), the Traffic view fed from its ring, the banner entry that
/// says where a saved recording is, and the File menu's "Save the last 10 minutes".
class RecordingController : public QObject {
    Q_OBJECT
public:
    /// The banner entry of a saved (or failed) black-box recording.
    static QString entryKey() { return QStringLiteral("blackBox"); }

    /// None of the arguments is owned; they must outlive the controller's use.
    RecordingController(BusController *controller, TrafficPanel *traffic, MessageBanner *banner,
                        QObject *parent = nullptr);

    BlackBoxRecorder *blackBox() const { return m_recorder; }
    BlackBoxTrafficFeed *trafficFeed() const { return m_feed; }
    /// Add the recording actions to the File menu.
    void addFileActions(QMenu *file);
    QAction *saveAction() const { return m_save; }

public slots:
    /// File -> Save the last 10 minutes.
    void saveNow();

private:
    /// The cause a save names (BlackBoxTriggers' reason names, or kOnRequest), worded.
    static QString causeText(const QString &why);
    void showSaved(const QString &why, const QString &path);
    void showSaveFailed(const QString &why, const QString &error);

    BusController *m_controller;
    MessageBanner *m_banner;
    BlackBoxRecorder *m_recorder;
    BlackBoxTrafficFeed *m_feed;
    QAction *m_save = nullptr;
};

} // namespace lk::ui
