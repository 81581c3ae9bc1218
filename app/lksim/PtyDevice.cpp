#include "PtyDevice.h"

#include <QtCore/QFile>
#include <QtCore/QFileInfo>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

namespace lk::app {

namespace {
QString sysError(const char *what)
{
    return QStringLiteral("%1: %2").arg(QString::fromLatin1(what),
                                        QString::fromLocal8Bit(strerror(errno)));
}
} // namespace

PtyDevice::~PtyDevice()
{
    close();
}

bool PtyDevice::open()
{
    m_master = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (m_master < 0) {
        m_error = sysError("posix_openpt");
        return false;
    }
    if (grantpt(m_master) != 0 || unlockpt(m_master) != 0) {
        m_error = sysError("grantpt/unlockpt");
        close();
        return false;
    }
    char name[256] = {};
    if (ptsname_r(m_master, name, sizeof name) != 0) {
        m_error = sysError("ptsname");
        close();
        return false;
    }
    m_slavePath = QString::fromLocal8Bit(name);
    // Hold the slave open ourselves: without it the master reads EIO whenever no client has
    // the device open, and the raw settings below would be lost on the client's first open.
    m_slaveKeepAlive = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_slaveKeepAlive < 0) {
        m_error = sysError("open slave");
        close();
        return false;
    }
    termios tio{};
    if (tcgetattr(m_slaveKeepAlive, &tio) == 0) {
        cfmakeraw(&tio);
        tio.c_cflag |= CLOCAL | CREAD;
        cfsetispeed(&tio, B115200);
        cfsetospeed(&tio, B115200);
        tcsetattr(m_slaveKeepAlive, TCSANOW, &tio);
    }
    return true;
}

bool PtyDevice::linkTo(const QString &path)
{
    const QFileInfo info(path);
    if (info.exists() || info.isSymLink()) {
        if (!info.isSymLink()) {
            m_error = QStringLiteral("%1 exists and is not a symlink; not replacing it").arg(path);
            return false;
        }
        QFile::remove(path);
    }
    if (::symlink(m_slavePath.toLocal8Bit().constData(), path.toLocal8Bit().constData()) != 0) {
        m_error = sysError("symlink");
        return false;
    }
    m_linkPath = path;
    return true;
}

void PtyDevice::close()
{
    if (!m_linkPath.isEmpty()) {
        QFile::remove(m_linkPath);
        m_linkPath.clear();
    }
    if (m_slaveKeepAlive >= 0)
        ::close(m_slaveKeepAlive);
    if (m_master >= 0)
        ::close(m_master);
    m_slaveKeepAlive = m_master = -1;
}

QByteArray PtyDevice::readAvailable()
{
    QByteArray out;
    char buf[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buf, sizeof buf);
        if (n > 0) {
            out.append(buf, n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break; // EAGAIN: drained; 0 or EIO: nothing to read now
    }
    return out;
}

bool PtyDevice::writeAll(const QByteArray &bytes)
{
    return writeAllTo(m_master, bytes);
}

qsizetype PtyDevice::writeDiscardingUnread(const QByteArray &bytes)
{
    qsizetype discarded = 0;
    qsizetype done = 0;
    int full = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_master, bytes.constData() + done, bytes.size() - done);
        if (n > 0) {
            done += n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && errno == EAGAIN) {
            if (++full > 100) { // the queue stays full even when emptied: give these bytes up
                discarded += bytes.size() - done;
                break;
            }
            int queued = 0;
            if (ioctl(m_slaveKeepAlive, FIONREAD, &queued) == 0)
                discarded += queued;
            tcflush(m_slaveKeepAlive, TCIFLUSH);
        } else {
            m_error = sysError("write");
            return -1;
        }
    }
    return discarded;
}

bool PtyDevice::writeToSlave(const QByteArray &bytes)
{
    return writeAllTo(m_slaveKeepAlive, bytes);
}

bool PtyDevice::writeAllTo(int fd, const QByteArray &bytes)
{
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.constData() + done, bytes.size() - done);
        if (n > 0) {
            done += n;
        } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
            usleep(100); // the reader is not reading: wait for room
        } else {
            m_error = sysError("write");
            return false;
        }
    }
    return true;
}

} // namespace lk::app
