#pragma once

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QString>

#include <fcntl.h>

namespace lk::testsupport {

/// How process `pid` holds `path` open: O_RDONLY, O_WRONLY or O_RDWR from its descriptor's
/// flags (/proc/PID/fdinfo), or -1 when it holds no descriptor on it. A listen-only port must
/// be held O_RDONLY.
inline int accessModeOf(qint64 pid, const QString &path)
{
    const QDir fds(QStringLiteral("/proc/%1/fd").arg(pid));
    for (const QString &fd : fds.entryList(QDir::NoDotAndDotDot | QDir::System | QDir::Files)) {
        if (QFileInfo(fds.filePath(fd)).symLinkTarget() != path)
            continue;
        QFile info(QStringLiteral("/proc/%1/fdinfo/%2").arg(pid).arg(fd));
        if (!info.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &line : info.readAll().split('\n')) {
            if (line.startsWith("flags:"))
                return int(line.mid(6).trimmed().toInt(nullptr, 8)) & O_ACCMODE;
        }
    }
    return -1;
}

} // namespace lk::testsupport
