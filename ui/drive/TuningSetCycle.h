#pragma once

#include "DriveView.h"
#include "ParamSetSpec.h"

#include <QtCore/QHash>
#include <QtCore/QObject>
#include <QtCore/QTime>

#include <optional>

namespace lk::ui {

class ParamExchange;
class ParameterTable;
class RequestTracker;

/// The read / write / read-back cycle of the Tuning view's set (ParamSetSpec) on the drive a
/// DriveView has selected, over a ParamExchange, and what it remembers of each drive: the first
/// complete read on this connection (what "restore" writes back), an unsent edit while another
/// drive is selected, and the last ROM write and RAM writes of the session (the RAM/ROM note).
///
/// Never writes what was not read: a write (RAM, ROM, restore) goes out only after a complete
/// read (every value of the set answered) of that drive on this connection, checked again after
/// the confirmation; another drive, another session or a reconnection starts over. A ROM write
/// and a restore ask first; declining sends nothing. Each frame of a write is sent once, a ROM
/// frame never again (ParamExchange), and every write is read back and compared.
class TuningSetCycle : public QObject {
    Q_OBJECT
public:
    enum class WriteKind { Ram, Rom, RestoreFirstRead };
    /// What RAM holds compared with ROM, for the selected drive.
    struct RamRomNote {
        QString text;
        bool warning = false; ///< RAM differs from the last ROM write, or was changed only there
    };

    /// Works on `view`'s drive through `tracker` (the view's), with `table` as the pending edit
    /// and the "first read" / "drive holds" columns. None is owned.
    TuningSetCycle(DriveView *view, RequestTracker *tracker, ParameterTable *table);

    /// The set of the selected drive's generation (not owned).
    void setSpec(const ParamSetSpec *spec);
    /// The view's session, drive or link changed: what was read is void; what belongs to one
    /// connection (first reads, unsent edits) goes with it, a session forgets everything, and
    /// the edit of the drive left behind is kept for it.
    void contextChanged(DriveView::Changes changes);
    /// Nothing of the selected drive is known any more (another drive, generation or link).
    void startOver();
    /// The table shows the selected drive now.
    void showDrive();

    /// Reads the set; `takePending`: the pending edit becomes what the drive holds.
    void read(bool takePending);
    /// The operator's read: keeps an edit in progress.
    void readFromDrive();
    /// Writes the pending edit (RAM, ROM) or the first read (restore), after asking where
    /// that is the rule, then reads back.
    void write(WriteKind kind);

    bool isBusy() const;
    bool readComplete() const { return m_readComplete; }
    HeldValues held() const;
    /// When the selected drive was first read completely on this connection (nullopt: not yet).
    std::optional<QTime> firstReadAt() const;
    RamRomNote ramRomNote() const;
    QString status() const { return m_status; }
    void setStatus(const QString &text, bool error = false);

signals:
    void statusChanged(const QString &text, bool error);
    /// How the last read-back differs from what was written (empty: hide it).
    void mismatchChanged(const QString &text);
    /// Every frame of a write was acknowledged (before its read-back is compared).
    void writeAcknowledged(bool rom);
    /// A read (or a write's read-back) of drive `id` completed.
    void readFinished(int id);
    /// What may be done now changed (buttons, editing).
    void stateChanged();

private:
    /// What the cycle remembers about a drive: reads and edits while the connection lasts
    /// (the next connection may reach other drives at the same IDs), writes for the session.
    struct DriveMemory {
        protocol::Generation generation = protocol::Generation::V2_3; ///< of the values below
        std::optional<ParamValues> firstRead; ///< first complete read on this connection
        QTime firstReadAt;
        std::optional<ParamValues> unsentEdit; ///< kept while another drive was selected
        std::optional<ParamValues> lastRom;    ///< last ROM write this session
        QVector<int> romFields;                ///< the fields of lastRom that went to ROM
        bool ramWritten = false; ///< RAM gains written this session after the last ROM write
    };

    void forgetOtherGeneration();
    void keepUnsentEdit();
    void onReadDone(int id);
    void takeReadValues(DriveMemory &mem);
    /// Writing is possible now; otherwise says why in the status line.
    bool mayWrite();
    bool confirmWrite(WriteKind kind, int id, const ParamValues &values);
    void onRomWritten(int id, const ParamValues &values, const QVector<int> &fields);
    void checkReadBack(const SentValues &sent);

    DriveView *m_view;
    RequestTracker *m_tracker;
    ParameterTable *m_table;
    ParamExchange *m_exchange;
    const ParamSetSpec *m_spec = nullptr;
    QHash<int, DriveMemory> m_memory; ///< per drive ID, for this session
    int m_shownId = 0; ///< the drive the table shows (the view's ID has already changed)
    bool m_readComplete = false;
    bool m_takePending = false;
    QString m_status;
};

} // namespace lk::ui
