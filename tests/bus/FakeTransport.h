#pragma once

#include "FakeDrives.h"

#include <transport/Transport.h>

#include <QtCore/QByteArray>
#include <QtCore/QMutex>
#include <QtCore/QVector>

#include <functional>
#include <memory>

namespace lk::bustest {

/// What a FakeTransport saw, readable from the test thread while the transport lives on a
/// bus thread.
struct FakeLog {
    mutable QMutex mutex;
    QVector<QByteArray> written;
    int opens = 0;
    QVector<bool> readOnly; ///< Transport::isReadOnly() at each open
    QVector<int> bauds;     ///< baud of each transport the factory made
    QVector<QByteArray> writtenCopy() const
    {
        QMutexLocker lock(&mutex);
        return written;
    }
};

/// A scripted Transport for bus tests. Each write is answered by the responder (by default
/// the FakeDrives table) after `replyDelayMs` (0: queued delivery, never inside write()).
/// Delays run on QTimer, or on the scheduler a test sets (a clock it advances by hand).
class FakeTransport : public transport::Transport {
    Q_OBJECT
public:
    /// Bytes to deliver for one written request frame (empty: stay silent). `index` counts
    /// writes from 0.
    using Responder = std::function<QByteArray(const protocol::Frame &request, int index)>;
    /// Runs a callback `ms` from now on the test's clock.
    using Scheduler = std::function<void(int ms, std::function<void()> f)>;

    explicit FakeTransport(int baud = 115200, std::shared_ptr<FakeLog> log = {},
                           QObject *parent = nullptr);

    bool open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    State state() const override { return m_state; }
    int baud() const override { return m_baud; }
    QString description() const override;

    FakeDrives &drives() { return m_drives; }
    void setResponder(Responder r) { m_responder = std::move(r); }
    void setReplyDelayMs(int ms) { m_delayMs = ms; }
    void setScheduler(Scheduler s) { m_scheduler = std::move(s); }
    /// Run `f` `ms` from now (on the scheduler if set, else a QTimer); never after this dies.
    void after(int ms, std::function<void()> f);
    void setLocalEcho(bool on) { m_localEcho = on; } ///< deliver each write back first
    void setFailOpen(bool fail) { m_failOpen = fail; }
    /// The adapter vanishes: Unplugged error, then state Disconnected.
    void unplug();
    /// Deliver bytes as if received (queued).
    void inject(const QByteArray &bytes);
    const std::shared_ptr<FakeLog> &log() const { return m_log; }
    int writes() const { return m_index; }

    /// The default answer (the drive table) for use inside custom responders.
    QByteArray defaultReply(const protocol::Frame &request) const;

private:
    void deliver(const QByteArray &bytes, int delayMs);
    void setState(State s);

    int m_baud;
    std::shared_ptr<FakeLog> m_log;
    FakeDrives m_drives;
    Responder m_responder;
    Scheduler m_scheduler;
    int m_delayMs = 0;
    int m_index = 0;
    bool m_localEcho = false;
    bool m_failOpen = false;
    State m_state = State::Closed;
};

} // namespace lk::bustest
