#pragma once

#include "FleetReader.h"
#include "RestorePlan.h"

#include <bus/RequestResult.h>

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QStringList>
#include <QtCore/QVector>

namespace lk::bus {
class BusSession;
}

namespace lk::fleet {

/// What a restore did to one target drive.
struct DriveReport {
    enum class Outcome {
        Verified,  ///< written and read back equal (ROM too, where the generation reads it)
        Written,   ///< acknowledged, but not all of it could be verified (notVerified says what)
        Unchanged, ///< the drive already held every value; nothing was sent
        Differs,   ///< the read-back differs from what was written (mismatches)
        Refused,   ///< nothing was sent (refusal)
        Failed,    ///< a write or the read-back did not complete (reason)
    };
    int sourceId = 0;
    int targetId = 0;
    Outcome outcome = Outcome::Refused;
    std::optional<Refusal> refusal;
    QString reason;               ///< Failed: what did not complete
    QVector<ParamChange> changes; ///< what the plan changed
    bool ramWritten = false;      ///< RAM frames were acknowledged
    int romFramesSent = 0;        ///< ROM frames that went out (each once)
    bool romAcknowledged = false; ///< every ROM frame was acknowledged
    QStringList mismatches;       ///< "angle_kp: wrote 100, reads 90"
    QStringList notVerified;      ///< what could not be checked, and why
    QStringList notes;            ///< what the user must know (CAN V2.36: RAM only)
    DriveSnapshot after;          ///< the last read-back (empty when none)

    static const char *outcomeName(Outcome o); ///< "verified", "written", ...
};

/// Restores parameters onto target drives in two steps. prepare() reads every target (its
/// values become the undo) and plans each restore (RestorePlan: refused, or the exact
/// changes); nothing is written. execute() then writes each planned target: RAM first (only
/// the values that change), reads back and compares; with `rom`, and only for a target whose
/// RAM read-back matched, the ROM frames go out once each, never retried (a lost reply stops
/// that drive's ROM writes), and the drive is read back again. A CAN V2.36 target has no ROM:
/// with `rom` it is refused, nothing sent; without, its report notes that it is RAM only.
class FleetRestore : public QObject {
    Q_OBJECT
public:
    explicit FleetRestore(bus::BusSession *session, QObject *parent = nullptr);

    /// One restore: `source` (from a backup, or a drive read just now) onto drive `targetId`.
    struct Job {
        DriveSnapshot source;
        int targetId = 0;
    };
    /// Reads every target and plans; prepared() follows.
    void prepare(const QVector<Job> &jobs);
    const QVector<RestorePlan> &plans() const { return m_plans; }
    /// The targets as read by prepare(), for the undo file.
    QVector<DriveSnapshot> undo() const;

    /// Writes the plans prepare() made (RAM; then ROM when `rom`); finished() follows.
    void execute(bool rom);
    const QVector<DriveReport> &reports() const { return m_reports; }
    bool busy() const { return m_busy; }

signals:
    void prepared();
    /// Target `done` of `total` is finished (prepare: read; execute: written).
    void progress(int done, int total);
    void finished();

private:
    enum class Stage { Ram, ReadBack, Rom, RomReadBack };
    void nextPlan();
    void startStage(Stage stage);
    void sendNextFrame();
    void onFrame(const ParamFrame &frame, const bus::RequestResult &r);
    void onReadBack();
    void endDrive(DriveReport::Outcome outcome);

    QPointer<bus::BusSession> m_session;
    FleetReader m_reader;
    QVector<Job> m_jobs;
    QVector<RestorePlan> m_plans;
    QVector<DriveReport> m_reports;
    QVector<ParamFrame> m_frames; ///< still to send for the current drive
    DriveReport m_report;
    Stage m_stage = Stage::Ram;
    bool m_rom = false;
    bool m_preparing = false;
    bool m_busy = false;
};

} // namespace lk::fleet
