#pragma once

#include <QtCore/QObject>

class QSocketNotifier;

namespace lk::lkctl {

/// Turns SIGINT and SIGTERM into a Qt signal (self-pipe), so that `lkctl monitor` ends
/// cleanly: polling stops, the last rows and the statistics are printed, the port is closed.
/// One instance at a time; the previous handlers are restored after the first signal (a
/// second one is not swallowed) and on destruction.
class SignalWatcher : public QObject {
    Q_OBJECT
public:
    explicit SignalWatcher(QObject *parent = nullptr);
    ~SignalWatcher() override;

    bool isValid() const { return m_notifier != nullptr; }

signals:
    void signalled(int signalNumber);

private:
    void onReadable();
    QSocketNotifier *m_notifier = nullptr;
};

} // namespace lk::lkctl
