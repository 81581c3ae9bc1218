#pragma once

#include "RecordingFormat.h"

#include <optional>

namespace lk::recording {

/// A recording file being written: unbuffered POSIX writes, so what write() accepted is the
/// kernel's (a killed process loses nothing written), and errno tells a full disk apart.
class RecordFile {
public:
    RecordFile() = default;
    ~RecordFile() { close(); }
    RecordFile(const RecordFile &) = delete;
    RecordFile &operator=(const RecordFile &) = delete;

    /// Create or truncate `path`.
    std::optional<RecordingError> create(const QString &path);
    std::optional<RecordingError> write(const QByteArray &bytes);
    void close();
    bool isOpen() const { return m_fd >= 0; }

private:
    int m_fd = -1;
    QString m_path;
};

} // namespace lk::recording
