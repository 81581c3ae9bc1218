#pragma once

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QString>

#include <sys/stat.h>

namespace lk::testsupport {

/// Files a reader must refuse without hanging or filling memory: a FIFO nobody writes to, a
/// directory, a device, and a sparse file of any size (no disk space, no time to write).
class OddFiles {
public:
    enum class Kind { Fifo, Directory, Device, Huge };

    /// Makes `kind` at `path` (Device: returns "/dev/zero" and makes nothing). Empty when it
    /// could not be made.
    static QString make(Kind kind, const QString &path, qint64 hugeBytes = 0)
    {
        switch (kind) {
        case Kind::Fifo:
            return ::mkfifo(QFile::encodeName(path).constData(), 0600) == 0 ? path : QString();
        case Kind::Directory:
            return QDir().mkpath(path) ? path : QString();
        case Kind::Device:
            return QStringLiteral("/dev/zero");
        case Kind::Huge: {
            QFile f(path);
            return f.open(QIODevice::WriteOnly) && f.resize(hugeBytes) ? path : QString();
        }
        }
        return {};
    }
};

} // namespace lk::testsupport
