#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace lk::recording {
class RecordingReader;
}

namespace lk::lkctl {

class Console;

/// `lkctl decode` on a recording (docs/RECORDING.md): the CLI.md object of every frame and
/// fault, each with "time_s" (session seconds, recordTimeText) and "wire" ("tx": sent by the
/// recording tool, "rx": received), decoded with the context recorded for its moment; link events
/// and drops as {"note":...}. Returns the exit status: 3 if a fault or damage was met.
int decodeRecording(recording::RecordingReader &reader, Console &console);

/// A record's session time (ns) as time_s: seconds to the microsecond, fixed six decimals
/// ("0.000300"), as monitor, replay and the CSV exports write it (TelemetryCsv::kTimeDecimals).
QByteArray recordTimeText(qint64 timeNs);

/// `object` as one JSON line with "time_s" (recordTimeText) and, when given, "wire" last.
QByteArray timedJsonLine(const QJsonObject &object, qint64 timeNs, const char *wire = nullptr);

/// True if `path` names a file that starts with the recording magic.
bool isRecordingFile(const QString &path);

} // namespace lk::lkctl
