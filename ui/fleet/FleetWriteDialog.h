#pragma once

#include <fleet/FleetRestore.h>

#include <QtWidgets/QDialog>

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

/// Restore or clone in the GUI: on opening it reads every target (their values are saved to
/// an undo file before anything is written) and shows exactly what will change, or why a
/// target is refused. Only then can RAM be written (and read back); ROM asks first, comes
/// after a RAM read-back that matched, and is sent once. A refused target is never written;
/// the others are. The report says per drive what was written, verified or not.
class FleetWriteDialog : public QDialog {
    Q_OBJECT
public:
    FleetWriteDialog(bus::BusSession *session, const QVector<fleet::FleetRestore::Job> &jobs,
                     const QString &title, const QString &undoPath, QWidget *parent = nullptr);

    bool prepared() const { return m_prepared; }
    bool finished() const { return m_finished; }
    const fleet::FleetRestore &restore() const { return m_restore; }
    QString text() const; ///< the diff and the report as shown
    QString undoPath() const { return m_undoPath; }

private:
    void onPrepared();
    void write(bool rom);
    void onFinished();
    QString planText(const fleet::RestorePlan &plan) const;
    /// Whether the target of `plan` has a ROM for these parameters (not CAN V2.36).
    static bool hasRom(const fleet::RestorePlan &plan);
    QString reportText(const fleet::DriveReport &report) const;

    fleet::FleetRestore m_restore;
    QString m_undoPath;
    QLabel *m_state;
    QPlainTextEdit *m_text;
    QPushButton *m_ram;
    QPushButton *m_rom;
    bool m_prepared = false;
    bool m_finished = false;
};

} // namespace lk::ui
