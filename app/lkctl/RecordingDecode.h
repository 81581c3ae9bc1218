#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace lk::recording {
class RecordingReader;
}

namespace lk::lkctl {

class Console;

/// `lkctl decode` on a recording (docs/RECORDING.md): the CLI.md object of every frame and
/// fault, each with "time_s" (session seconds) and "wire" ("tx": sent by the recording tool,
/// "rx": received), decoded with the context recorded for its moment; link events and drops
/// as {"note":...}. Returns the exit status: 3 if a fault or damage was met.
int decodeRecording(recording::RecordingReader &reader, Console &console);

/// True if `path` names a file that starts with the recording magic.
bool isRecordingFile(const QString &path);

} // namespace lk::lkctl
