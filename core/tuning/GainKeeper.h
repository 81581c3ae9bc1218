#pragma once

#include "LoopGains.h"

#include <QtCore/QObject>
#include <QtCore/QString>

#include <functional>
#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::tuning {

/// Reads a drive's loop gains on this connection and writes gains to its RAM: a frequency
/// sweep or a gain search runs only once read() succeeded, and puts the read gains back with
/// restore() when it ends or is aborted. Only gains derived from the read set are ever written
/// (never what was not read); never ROM. Lives in the session's thread.
class GainKeeper : public QObject {
    Q_OBJECT
public:
    /// `ok`; otherwise `why` (English) says which request failed.
    using Done = std::function<void(bool ok, const QString &why)>;

    explicit GainKeeper(bus::BusSession &session, QObject *parent = nullptr);

    /// Reads every loop's gains of `id` (LoopGains::reads of its generation on the session).
    void read(int id, Done done);
    /// The gains read on this connection; nullopt before read() succeeded.
    const std::optional<LoopGains> &gains() const { return m_read; }
    /// Writes `gains` (of the read drive's generation) to RAM; refused before a read.
    void write(const LoopGains &gains, Done done);
    /// write() of the gains read.
    void restore(Done done);
    /// What the drive's RAM holds as far as this keeper wrote or read it.
    const std::optional<LoopGains> &inRam() const { return m_inRam; }
    int id() const { return m_id; }

private:
    void sendAll(const QVector<protocol::Request> &requests, quint64 run,
                 std::function<void(const QVector<protocol::Reply> &)> ok, Done done);

    bus::BusSession &m_session;
    int m_id = 0;
    std::optional<LoopGains> m_read;
    std::optional<LoopGains> m_inRam;
    quint64 m_run = 0; ///< a late completion of an earlier exchange is ignored
};

} // namespace lk::tuning
