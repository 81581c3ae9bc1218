#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace lk::e2e {

/// One lksim process serving a simulated bus on a pseudo-terminal, for end-to-end tests and
/// benchmarks: started with its arguments, it prints the device path as its first line.
class LksimProcess {
public:
    explicit LksimProcess(QString executable);
    ~LksimProcess(); ///< stop()

    /// Start `lksim ARGS` and wait (generously) for the device path. False on failure, with
    /// the reason in errorString().
    bool start(const QStringList &args);
    /// SIGTERM, then SIGKILL if it does not end within 5 s.
    void stop();
    /// SIGKILL: the "adapter" vanishes without a goodbye.
    void kill();
    bool isRunning() const { return m_process.state() != QProcess::NotRunning; }

    QString devicePath() const { return m_device; }
    QString errorString() const { return m_error; }
    /// Everything lksim wrote on standard error so far (its --verbose frame log).
    QByteArray log();
    /// Frames lksim received, from its --verbose log: upper-case hex lines after "<- ".
    QList<QByteArray> receivedFrames();

private:
    QString m_executable;
    QProcess m_process;
    QString m_device;
    QString m_error;
    QByteArray m_log;
};

} // namespace lk::e2e
