#pragma once

#include <QtCore/QObject>

class QSocketNotifier;

namespace lk::transport {

/// A single-shot wake-up at a nanosecond deadline, delivered by the owning thread's event
/// loop (a Linux timerfd behind a QSocketNotifier). QTimer waits whole milliseconds; a CAN
/// frame or a 4 Mbaud RS485 frame lasts a tenth of that, and polling the event loop until it
/// is due keeps a core busy for nothing.
class PreciseWake : public QObject {
    Q_OBJECT
public:
    explicit PreciseWake(QObject *parent = nullptr);
    ~PreciseWake() override;

    /// False where the system gave no timerfd: the caller keeps its own way of waiting.
    bool isValid() const { return m_fd >= 0; }
    /// Wakes once, `ns` from now (at once for 0 or less); replaces a wake-up already set.
    void wakeIn(qint64 ns);
    void cancel();
    bool isActive() const { return m_active; }

signals:
    void woke();

private:
    void onReadable();

    int m_fd = -1;
    QSocketNotifier *m_notifier = nullptr;
    bool m_active = false;
};

} // namespace lk::transport
