#pragma once

#include "DriveSnapshot.h"

#include <bus/RequestResult.h>

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QVector>

namespace lk::bus {
class BusSession;
}

namespace lk::fleet {

/// Reads every parameter of several drives, one drive after another: read_model (identity
/// and generation; on CAN, which has none, the identity the user declared to the session),
/// then the generation's reads (FleetCatalog). Reports progress per drive;
/// cancel() stops it after the drive being read (nothing already queued is abandoned, so the
/// bus stays in step). A failed read leaves its values unknown and says why.
class FleetReader : public QObject {
    Q_OBJECT
public:
    explicit FleetReader(bus::BusSession *session, QObject *parent = nullptr);

    /// Starts reading `ids` in order; a read already running is cancelled first.
    void start(const QVector<int> &ids);
    void cancel();
    bool running() const { return m_running; }
    bool cancelled() const { return m_cancelled; }
    /// The drives read so far, in the order asked.
    const QVector<DriveSnapshot> &snapshots() const { return m_snapshots; }

signals:
    /// One more drive has been read (or has failed); `done` of `total`.
    void driveRead(const lk::fleet::DriveSnapshot &snapshot, int done, int total);
    /// Every drive was read, or the read was cancelled (cancelled() says which).
    void finished();

private:
    void readNext();
    void onModel(const bus::RequestResult &r);
    void identifyOnCan();
    void readValues();
    void onValue(const bus::RequestResult &r);
    void finishDrive();

    QPointer<bus::BusSession> m_session;
    QVector<int> m_ids;
    QVector<DriveSnapshot> m_snapshots;
    DriveSnapshot m_current;
    QStringList m_failures;
    int m_outstanding = 0;
    quint64 m_run = 0; ///< completions of an earlier run are ignored
    bool m_running = false;
    bool m_cancelled = false;
};

} // namespace lk::fleet
