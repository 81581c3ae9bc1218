#pragma once

#include <QtCore/QString>
#include <QtCore/QVector>
#include <QtCore/QtGlobal>

namespace lk::system {

/// A process that has a file open.
struct FileHolder {
    qint64 pid = 0;
    QString command; ///< the program's name (argv[0] without its folder, else its comm)
    bool operator==(const FileHolder &o) const { return pid == o.pid && command == o.command; }
};

/// Which processes hold a file (a serial port) open, where the system tells: on Linux, every
/// /proc/PID/fd entry that is the same file. Processes the user may not look into are not
/// seen (root sees all); elsewhere the answer is empty. For "in use by another program".
class FileHolders {
public:
    /// The holders of `path` other than this process, by ascending PID; empty when none is
    /// seen (or the path does not exist).
    static QVector<FileHolder> of(const QString &path);
    /// The folder the processes are found in (tests point it elsewhere); default "/proc".
    static QVector<FileHolder> of(const QString &path, const QString &procRoot);
};

} // namespace lk::system
