#pragma once

#include <QtCore/QObject>

class QSocketNotifier;

namespace lk::system {

/// Turns SIGINT and SIGTERM into a Qt signal (self-pipe), so that a program ends the normal
/// way: `lkctl monitor` prints its last rows and statistics, lkstudio closes its window and
/// saves its settings. The handler only writes a byte; Qt is never called from it.
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

} // namespace lk::system
