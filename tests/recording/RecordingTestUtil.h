#pragma once

#include <recording/RecordEncoder.h>
#include <recording/RecordingReader.h>

#include <QtCore/QFile>
#include <QtCore/QVector>

namespace lk::testsupport {

/// A header as a test recording carries it.
inline recording::RecordingHeader testHeader()
{
    recording::RecordingHeader h;
    h.toolVersion = QStringLiteral("9.9.9-test");
    h.linkKind = recording::LinkKind::Serial;
    h.linkDescription = QStringLiteral("/dev/ttyTEST @ 115200");
    h.baud = 115200;
    h.wallClockStartMs = 1'800'000'000'000;
    h.context = {{1, protocol::Series::MS, protocol::Generation::V2_35}};
    return h;
}

/// Every record of a recording file; `error` gets the reader's error (None after a clean end).
inline QVector<recording::RecordEvent> readAll(const QString &path,
                                               recording::RecordingError *error = nullptr,
                                               recording::RecordingHeader *header = nullptr)
{
    recording::RecordingReader reader;
    QVector<recording::RecordEvent> out;
    if (reader.open(path)) {
        recording::RecordEvent e;
        while (reader.next(&e))
            out.append(e);
        if (header)
            *header = reader.header();
    }
    if (error)
        *error = reader.error();
    return out;
}

/// The lines of a program's output, without empty ones.
inline QList<QByteArray> lines(const QByteArray &out)
{
    QList<QByteArray> l = out.split('\n');
    l.removeAll(QByteArray());
    return l;
}

inline bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

} // namespace lk::testsupport
