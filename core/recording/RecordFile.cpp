#include "RecordFile.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QFile>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace lk::recording {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("lk::recording::RecordFile", text);
}

QString errnoText(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

} // namespace

std::optional<RecordingError> RecordFile::create(const QString &path)
{
    close();
    m_path = path;
    m_fd =
        ::open(QFile::encodeName(path).constData(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (m_fd >= 0)
        return std::nullopt;
    const int error = errno;
    return RecordingError{RecordingError::Kind::OpenFailed, -1,
                          tr("Cannot create the recording %1: %2.").arg(path, errnoText(error))};
}

std::optional<RecordingError> RecordFile::write(const QByteArray &bytes)
{
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_fd, bytes.constData() + done, size_t(bytes.size() - done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            const bool full = error == ENOSPC || error == EDQUOT || error == EFBIG;
            return RecordingError{
                full ? RecordingError::Kind::DiskFull : RecordingError::Kind::WriteFailed, -1,
                (full ? tr("Recording stopped: the disk holding %1 is full (%2).")
                      : tr("Recording stopped: cannot write %1 (%2)."))
                    .arg(m_path, errnoText(error))};
        }
        done += n;
    }
    return std::nullopt;
}

void RecordFile::close()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
}

} // namespace lk::recording
