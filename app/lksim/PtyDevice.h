#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace lk::app {

/// The master side of a new pseudo-terminal in raw 8N1 mode: the slave is a serial device
/// that any program (QSerialPort, minicom, lkctl) can open.
class PtyDevice {
public:
    PtyDevice() = default;
    ~PtyDevice();
    PtyDevice(const PtyDevice &) = delete;
    PtyDevice &operator=(const PtyDevice &) = delete;

    /// Create the pty; on failure returns false and sets errorString().
    bool open();
    /// Make `path` a symlink to the slave device (an existing symlink is replaced, any other
    /// file is left alone and reported as an error).
    bool linkTo(const QString &path);
    void close();

    int masterFd() const { return m_master; }
    QString slavePath() const { return m_slavePath; }
    QString errorString() const { return m_error; }

    /// Read what the client wrote; empty when nothing is there.
    QByteArray readAvailable();
    /// Write all bytes (blocking until the kernel took them); false on error.
    bool writeAll(const QByteArray &bytes);
    /// Write without waiting for a reader, as a tap does: when the client's input queue is full
    /// (nobody reads), its unread bytes are discarded and the write goes on. Returns how many
    /// bytes were discarded, or -1 on error.
    qsizetype writeDiscardingUnread(const QByteArray &bytes);
    /// Write bytes as a client would, to the slave (they read back from the master, the path
    /// PtyLagProbe times); false on error.
    bool writeToSlave(const QByteArray &bytes);

private:
    bool writeAllTo(int fd, const QByteArray &bytes);

    int m_master = -1;
    int m_slaveKeepAlive = -1; ///< keeps the pty alive while no client has it open
    QString m_slavePath;
    QString m_linkPath;
    QString m_error;
};

} // namespace lk::app
