#pragma once

#include <protocol/Series.h>

#include <QtCore/QObject>
#include <QtCore/QString>

#include <optional>

class QPushButton;
class QWidget;

namespace lk::ui {

class AppSettings;
class BusController;
class DriveSettingsStore;
class SeriesChooser;

/// What lkstudio does around a listen-only link, beside the views' own gating (BusModel::
/// canSend): "Take over the bus" only after the user confirmed what it means; the emergency
/// stop button says that it sends nothing while listening; and a drive's series the user chose
/// (SeriesChooser) is remembered per port and ID and applied to the bus, again whenever that
/// drive is seen on that port. The same holds on CAN, which has no model read: there the
/// chooser also takes the gear ratio, kept in the drive views' store (the Encoder view's),
/// and the generation where no reply told it; series, generation and ratio go to the bus
/// together as the drive's identity (BusSession::setDriveIdentity) once series and
/// generation are known.
class ListenOnlyControl : public QObject {
    Q_OBJECT
public:
    /// None of the arguments is owned; `dialogParent` parents the confirmation.
    ListenOnlyControl(BusController *controller, AppSettings *settings, SeriesChooser *chooser,
                      QPushButton *stopButton, QWidget *dialogParent);

    /// The confirmation's key (ConfirmDialog policies in tests).
    static QString takeOverKey() { return QStringLiteral("take_over_bus"); }
    /// Where chosen gear ratios are kept (the drive views' store; not owned). Without one a
    /// ratio applies to the drives shown until they go.
    void setDriveStore(DriveSettingsStore *store);

public slots:
    /// Ask, then take the bus over (BusController::takeOver) if the user agreed and the link
    /// still listens; nothing happens otherwise.
    void requestTakeOver();

private:
    void chooseSeries(int id, protocol::Series series);
    void chooseGearRatio(int id, double ratio);
    void chooseGeneration(int id, protocol::Generation generation);
    /// Give the bus what is known of drive `id`: on CAN its identity once series and
    /// generation are known, else its series alone.
    void applyChoice(int id, std::optional<protocol::Series> series);
    void applyRemembered();
    void syncStopButton();

    BusController *m_controller;
    AppSettings *m_settings;
    SeriesChooser *m_chooser;
    QPushButton *m_stop;
    DriveSettingsStore *m_store = nullptr;
    QWidget *m_dialogParent;
    QString m_stopTip; ///< the stop button's own tooltip
};

} // namespace lk::ui
