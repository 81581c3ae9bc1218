#pragma once

#include "StepRun.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// Why a run file was refused. Core names the file, the key or line and what was found; the UI
/// words it (toString() is an English line for logs and tests, not for the UI).
struct StepRunFileError {
    enum class Kind {
        CannotRead,          ///< path, detail: the file system's reason, or what the path
                             ///< is instead of a regular file (a directory, a FIFO, ...)
        TooLarge,            ///< path (the JSON or a CSV), max: the limit in bytes, found:
                             ///< the file's size, detail: both in words
        NotJson,             ///< path, detail: the parser's reason, offset: where
        NotObject,           ///< path: the document is not a JSON object
        WrongFormat,         ///< path, found: "format" is not kFormatName
        NewerVersion,        ///< path, found: the file's version, max: the newest this reads
        MissingKey,          ///< path, key
        UnknownKey,          ///< path, key: a key this format does not have
        DuplicateKey,        ///< path, key: a top-level key given twice
        WrongType,           ///< path, key, expected (min..max for numbers), found
        OutOfRange,          ///< path, key, expected, min..max, found
        BadText,             ///< path, key, found: a text that means nothing there (a loop
                             ///< word, a date, a series, a trace file name with a folder)
        EdgesNotAscending,   ///< path, key: an edge earlier than the one before it
        MissingTrace,        ///< path: the CSV a run names, key: where, detail: why unreadable
        CsvBadHeader,        ///< path, line 1, found: not "time_s,value,effort"
        CsvBadRow,           ///< path, line, found: not three cells
        CsvBadNumber,        ///< path, line, column, found: not a finite number
        CsvTimeNotAscending, ///< path, line, found: time_s before the line before's
    };
    /// What a key must hold.
    enum class ValueType { Integer, Number, Text, Object, Array };

    Kind kind = Kind::NotJson;
    QString path;   ///< the file at fault: the JSON file, or the run's CSV
    QString key;    ///< JSON: path from the top, e.g. "runs[1].gains.speed_kp"
    int line = 0;   ///< CSV: 1-based line
    QString column; ///< CSV: "time_s", "value" or "effort"
    ValueType expected = ValueType::Integer;
    double min = 0; ///< allowed range (Integer, Number), inclusive
    double max = 0;
    QString found;      ///< what the file holds there, as JSON text or the CSV cell
    qint64 offset = -1; ///< NotJson: byte offset of the fault
    QString detail;     ///< CannotRead, NotJson, MissingTrace: the system's or parser's reason

    /// One English line naming the file and the key or line, for logs and test messages.
    QString toString() const;
};

/// Saves and loads a set of kept step runs (#13), so a technician can compare today's motor
/// with last week's.
///
/// Layout: `NAME.lkruns.json` holds {"format":"lkstudio-step-runs","version":1,"runs":[...]},
/// every run with its identity, test, gains, ramps, effort kind and limit, edges and the name
/// of its trace file; the trace samples go to `NAME.run1.csv`, `NAME.run2.csv`, ... (by
/// position in the set) beside it, named in the run's "trace" key without a folder. The CSV is
/// `time_s,value,effort`, one line per sample, C locale; an effort the sample did not carry is
/// an empty cell, never 0. Times in both files count from the run's first edge (from its first
/// sample when it has no edge), so a loaded run's first edge is at 0 s. Each run also carries
/// "metrics" (StepRunJson::metricsObject() of its first edge) for readers of the file; loading
/// ignores them and the metrics are computed from the trace again.
class StepRunFile {
public:
    static constexpr char kFormatName[] = "lkstudio-step-runs";
    static constexpr int kFormatVersion = 1;
    static constexpr char kSuffix[] = ".lkruns.json";
    /// Size bounds: load() refuses a larger file unread, save() refuses to write one. A
    /// trace of 16 MiB holds about half a million samples (a 100-period square of 1 s steps
    /// at 2 kHz); a set's traces hold 64 MiB together.
    static constexpr qint64 kMaxJsonBytes = 16 * 1024 * 1024;
    static constexpr qint64 kMaxTraceBytes = 16 * 1024 * 1024;
    static constexpr qint64 kMaxSetTraceBytes = 64 * 1024 * 1024;

    /// The CSV file name of the run at `index` (0-based) of a set saved as `jsonPath`:
    /// "NAME.run<index + 1>.csv", NAME being the file name without kSuffix (or ".json").
    static QString traceFileName(const QString &jsonPath, int index);

    /// Writes every run's CSV, then the JSON file, each atomically (system::AtomicFile): a file
    /// either holds its complete new content or what it held before. The JSON is written last, so
    /// it never names a CSV that failed. Returns an error text, empty on success.
    static QString save(const QString &jsonPath, const QVector<StepRun> &runs);
    /// Reads a set saved by save(). Anything missing, unknown, of the wrong type, out of range
    /// or unreadable, in the JSON file or any CSV, refuses the whole set (nullopt) with `error`
    /// naming the file and the key or line.
    static std::optional<QVector<StepRun>> load(const QString &jsonPath,
                                                StepRunFileError *error = nullptr);

    /// The JSON document of `runs`, naming `traceNames[i]` as run i's trace.
    static QJsonObject toJson(const QVector<StepRun> &runs, const QStringList &traceNames);
    /// The time every time of a run's files counts from: its first edge, else its first
    /// sample, else 0.
    static double timeOrigin(const StepTrace &trace);

private:
    /// The CSV text of a run's trace (header included).
    static QByteArray traceCsv(const StepRun &run);
};

} // namespace lk::tuning
