#include "FileHolders.h"

#include "BoundedFile.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>

#include <algorithm>
#include <sys/stat.h>

namespace lk::system {

namespace {

constexpr qint64 kMaxProcTextBytes = 64 * 1024; // a command line, a comm

/// Whether `a` and `b` are the same file: the same device node, or the same inode.
bool sameFile(const struct stat &a, const struct stat &b)
{
    if (S_ISCHR(a.st_mode) || S_ISBLK(a.st_mode))
        return (a.st_mode & S_IFMT) == (b.st_mode & S_IFMT) && a.st_rdev == b.st_rdev;
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

QString commandOf(const QString &processDir)
{
    // argv[0] names the program as the user started it; comm is cut to 15 characters.
    const BoundedRead cmdline =
        BoundedFile::read(processDir + QStringLiteral("/cmdline"), kMaxProcTextBytes);
    if (cmdline.ok() && !cmdline.bytes.isEmpty()) {
        const QString argv0 =
            QString::fromLocal8Bit(cmdline.bytes.left(cmdline.bytes.indexOf('\0')));
        if (!argv0.isEmpty())
            return QFileInfo(argv0).fileName();
    }
    const BoundedRead comm =
        BoundedFile::read(processDir + QStringLiteral("/comm"), kMaxProcTextBytes);
    return comm.ok() ? QString::fromLocal8Bit(comm.bytes).trimmed() : QString();
}

} // namespace

QVector<FileHolder> FileHolders::of(const QString &path)
{
    return of(path, QStringLiteral("/proc"));
}

QVector<FileHolder> FileHolders::of(const QString &path, const QString &procRoot)
{
    QVector<FileHolder> holders;
    struct stat target {};
    if (::stat(QFile::encodeName(path).constData(), &target) != 0)
        return holders;
    const qint64 self = QCoreApplication::applicationPid();
    const QDir proc(procRoot);
    for (const QString &entry : proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        bool numeric = false;
        const qint64 pid = entry.toLongLong(&numeric);
        if (!numeric || pid == self)
            continue;
        const QString processDir = proc.filePath(entry);
        const QDir fds(processDir + QStringLiteral("/fd"));
        // stat() through the fd's link: the open file itself, without opening it again.
        for (const QString &fd :
             fds.entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot)) {
            struct stat st {};
            if (::stat(QFile::encodeName(fds.filePath(fd)).constData(), &st) == 0 &&
                sameFile(target, st)) {
                holders.append(FileHolder{pid, commandOf(processDir)});
                break;
            }
        }
    }
    std::sort(holders.begin(), holders.end(),
              [](const FileHolder &a, const FileHolder &b) { return a.pid < b.pid; });
    return holders;
}

} // namespace lk::system
