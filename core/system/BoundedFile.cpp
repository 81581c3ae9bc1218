#include "BoundedFile.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QFile>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lk::system {

namespace {

QString say(const char *text)
{
    return QCoreApplication::translate("lk::system::BoundedFile", text);
}

/// What a node that is not a regular file is, in words.
QString nodeKind(mode_t mode)
{
    if (S_ISDIR(mode))
        return say(QT_TRANSLATE_NOOP("lk::system::BoundedFile", "a directory"));
    if (S_ISFIFO(mode))
        return say(QT_TRANSLATE_NOOP("lk::system::BoundedFile", "a FIFO (named pipe)"));
    if (S_ISCHR(mode))
        return say(QT_TRANSLATE_NOOP("lk::system::BoundedFile", "a character device"));
    if (S_ISBLK(mode))
        return say(QT_TRANSLATE_NOOP("lk::system::BoundedFile", "a block device"));
    if (S_ISSOCK(mode))
        return say(QT_TRANSLATE_NOOP("lk::system::BoundedFile", "a socket"));
    return say(QT_TRANSLATE_NOOP("lk::system::BoundedFile", "not a regular file"));
}

BoundedRead failure(FileReadError::Kind kind, const QString &path, const QString &detail,
                    qint64 size = -1, qint64 maxBytes = 0)
{
    BoundedRead r;
    r.error = FileReadError{kind, path, detail, size, maxBytes};
    return r;
}

BoundedRead cannotOpen(const QString &path, int error)
{
    return failure(FileReadError::Kind::CannotOpen, path,
                   QString::fromLocal8Bit(std::strerror(error)));
}

} // namespace

QString FileReadError::reason() const
{
    switch (kind) {
    case Kind::CannotOpen:
        return detail;
    case Kind::NotRegularFile:
        return QCoreApplication::translate("lk::system::BoundedFile",
                                           "it is %1, not a regular file")
            .arg(detail);
    case Kind::TooLarge: {
        QString found = BoundedFile::sizeText(size);
        QString bound = BoundedFile::sizeText(maxBytes);
        if (found == bound) { // 16.8 MB and 16.8 MB: say the bytes
            found = QString::number(size);
            bound =
                QCoreApplication::translate("lk::system::BoundedFile", "%1 bytes").arg(maxBytes);
        }
        return QCoreApplication::translate("lk::system::BoundedFile",
                                           "it is %1, more than the %2 such a file may have")
            .arg(found, bound);
    }
    }
    return {};
}

QString FileReadError::toString() const
{
    return QCoreApplication::translate("lk::system::BoundedFile", "cannot read %1: %2")
        .arg(path, reason());
}

QString BoundedFile::sizeText(qint64 bytes)
{
    if (bytes < 1'000'000)
        return QCoreApplication::translate("lk::system::BoundedFile", "%1 bytes").arg(bytes);
    return QCoreApplication::translate("lk::system::BoundedFile", "%1 MB")
        .arg(double(bytes) / 1e6, 0, 'f', 1);
}

BoundedRead BoundedFile::read(const QString &path, qint64 maxBytes)
{
    const QByteArray name = QFile::encodeName(path);
    // Look before opening: opening a FIFO waits for a writer, and opening a device can have
    // effects of its own (a serial port's lines).
    struct stat st {};
    if (::stat(name.constData(), &st) != 0)
        return cannotOpen(path, errno);
    if (!S_ISREG(st.st_mode))
        return failure(FileReadError::Kind::NotRegularFile, path, nodeKind(st.st_mode));
    if (st.st_size > maxBytes)
        return failure(FileReadError::Kind::TooLarge, path, {}, st.st_size, maxBytes);
    // O_NONBLOCK: should the path have become a FIFO since stat(), open() still returns.
    const int fd = ::open(name.constData(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return cannotOpen(path, errno);
    struct stat opened {};
    if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
        ::close(fd);
        return failure(FileReadError::Kind::NotRegularFile, path, nodeKind(opened.st_mode));
    }
    // Read at most one byte past the bound: a file that grew since stat() is still refused.
    BoundedRead r;
    r.bytes.resize(qsizetype(std::min<qint64>(opened.st_size, maxBytes) + 1));
    qint64 total = 0;
    for (;;) {
        if (total == r.bytes.size()) {
            if (total > maxBytes)
                break;
            r.bytes.resize(qsizetype(std::min<qint64>(total * 2 + 4096, maxBytes + 1)));
        }
        const ssize_t n = ::read(fd, r.bytes.data() + total, size_t(r.bytes.size() - total));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            const int error = errno;
            ::close(fd);
            return cannotOpen(path, error);
        }
        if (n == 0)
            break;
        total += n;
    }
    ::close(fd);
    if (total > maxBytes)
        return failure(FileReadError::Kind::TooLarge, path, {}, total, maxBytes);
    r.bytes.truncate(qsizetype(total));
    return r;
}

} // namespace lk::system
