#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include <optional>

namespace lk::system {

/// Why a file the tool was given was not read.
struct FileReadError {
    enum class Kind {
        CannotOpen,     ///< detail: the system's reason (no such file, no permission, ...)
        NotRegularFile, ///< detail: what it is instead ("a directory", "a FIFO", ...)
        TooLarge,       ///< size: the file's size in bytes (at least), maxBytes: the bound
    };
    Kind kind = Kind::CannotOpen;
    QString path;
    QString detail;
    qint64 size = -1;
    qint64 maxBytes = 0;

    /// Why, without the path: the system's reason, "it is a directory, not a regular file",
    /// "it is 130.0 MB, more than the 33.6 MB such a file may have" (translated where a
    /// translator is installed).
    QString reason() const;
    /// "cannot read PATH: " and the reason.
    QString toString() const;
};

/// The bytes of a file, or why there are none.
struct BoundedRead {
    QByteArray bytes;
    std::optional<FileReadError> error;
    bool ok() const { return !error; }
};

/// Reads a whole file that a user or another program handed the tool (a limits file, a
/// parameter set, a step run, a settings file) with a bound on its size, so that /dev/zero,
/// a FIFO without a writer or a huge file can neither exhaust memory nor hang the tool: only
/// a regular file (symbolic links followed) is opened at all, and one larger than `maxBytes`
/// is refused with its size named. Each reader states its bound next to its format.
class BoundedFile {
public:
    static BoundedRead read(const QString &path, qint64 maxBytes);
    /// "65536 bytes" below a megabyte, "130.0 MB" above.
    static QString sizeText(qint64 bytes);
};

} // namespace lk::system
