#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QSaveFile>
#include <QtCore/QString>

namespace lk::system {

/// A file written so that its path holds either the whole new content or what it held before
/// (QSaveFile), also when the disk fills up: Qt 6.4's QSaveFile renames a cut copy into place
/// when the flush inside commit() fails, so commit() here flushes first, where a failure can
/// still cancel. An AtomicFile destroyed before commit() leaves the path as it was.
class AtomicFile {
public:
    explicit AtomicFile(const QString &path);
    ~AtomicFile(); ///< discards what was written unless committed
    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &operator=(const AtomicFile &) = delete;

    bool open();
    /// Appends `bytes`; false (and every later commit() fails) when not all were written.
    bool write(const QByteArray &bytes);
    /// The device, for writers that take one (QImageWriter). Call fail() when such a writer
    /// reports an error, so that commit() does not put its cut output in place.
    QIODevice *device() { return &m_file; }
    void fail(const QString &why);
    /// Flush, then rename into place; on any failure (this one or an earlier write) the
    /// path is left as it was and false is returned.
    bool commit();
    /// The first failure's reason (the system's words), empty while all went well.
    QString errorString() const { return m_error; }
    QString fileName() const { return m_file.fileName(); }

    /// Writes `bytes` to `path` in one go; the reason of a failure, empty on success.
    static QString writeAll(const QString &path, const QByteArray &bytes);

private:
    QSaveFile m_file;
    QString m_error;
    bool m_open = false;
};

} // namespace lk::system
