#pragma once

#include <fleet/DriveSnapshot.h>
#include <fleet/FleetReader.h>
#include <fleet/FleetRestore.h>

#include <QtCore/QPointer>
#include <QtWidgets/QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class FleetWriteDialog;

/// The parameters of the whole bus side by side: drives as columns, every parameter this tool
/// reads as rows (FleetGrid), read on this connection with progress and cancel. A reference
/// drive is chosen and the cells that differ from it are marked; "only rows that differ"
/// hides the rest. Back up writes the last read into a bus backup file; Restore and Clone
/// open a FleetWriteDialog, which reads the targets and shows the diff before writing.
class ParametersView : public QWidget {
    Q_OBJECT
public:
    explicit ParametersView(QWidget *parent = nullptr);

    void setSession(bus::BusSession *session);
    void setConnected(bool connected);
    /// The drives found on the bus; the columns of the next read.
    void setDrives(const QVector<int> &ids);

    void readAll();
    void cancelRead();
    /// Saves the last read (every drive of it) to `path`; an error text, empty on success.
    QString backupTo(const QString &path) const;
    /// Opens the restore dialog for the backup at `path`: each entry onto the same ID, or,
    /// when the ID map ("3:5,4:6") is filled in, only the mapped entries onto their new IDs.
    /// nullptr, with the reason in the status line, when the file or the map is refused.
    FleetWriteDialog *restoreFrom(const QString &path);
    /// Opens the clone dialog: the reference drive's values onto every other drive read.
    FleetWriteDialog *cloneReference();

    const QVector<fleet::DriveSnapshot> &snapshots() const { return m_snapshots; }
    QTableWidget *table() const { return m_table; }

private:
    void refill();
    void updateActions();
    void onDriveRead(const fleet::DriveSnapshot &snapshot, int done, int total);
    void onReadFinished();
    FleetWriteDialog *openWriteDialog(const QVector<fleet::FleetRestore::Job> &jobs,
                                      const QString &title);
    static QString undoPath();

    QPointer<bus::BusSession> m_session;
    fleet::FleetReader *m_reader = nullptr;
    QVector<int> m_ids;
    QVector<fleet::DriveSnapshot> m_snapshots;
    bool m_connected = false;
    QPushButton *m_read;
    QPushButton *m_cancel;
    QProgressBar *m_progress;
    QComboBox *m_reference;
    QCheckBox *m_onlyDiffering;
    QTableWidget *m_table;
    QPushButton *m_backup;
    QPushButton *m_restore;
    QLineEdit *m_idMap;
    QPushButton *m_clone;
    QLabel *m_status;
};

} // namespace lk::ui
