#pragma once

#include <protocol/Series.h>
#include <protocol/Values.h>

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QString>

#include <array>
#include <optional>

namespace lk::record {

/// Why a parameter file was refused. Core names the fault, the key and the allowed range;
/// the UI words it (ui/drive/ParameterFileText).
struct ParameterFileError {
    enum class Kind {
        CannotRead,        ///< detail: the file system's reason, or what the path is instead
                           ///< of a regular file (a directory, a FIFO, a device)
        TooLarge,          ///< bigger than any parameter file (max: the limit in bytes,
                           ///< found: the file's size, detail: both in words)
        NotJson,           ///< detail: the JSON parser's reason, offset: where
        NotObject,         ///< the document is not a JSON object
        WrongFormat,       ///< "format" is not "lkstudio-parameters" (found: what it is)
        NewerVersion,      ///< found: the file's version, max: the newest this release reads
        MissingKey,        ///< key
        UnknownKey,        ///< key: a key this format does not have
        DuplicateKey,      ///< key: a key given twice in one object
        WrongType,         ///< key, expected (and min..max for numbers), found
        OutOfRange,        ///< key, expected, min..max, found
        UnknownSeries,     ///< key, found: not MS, MF, MG or MH
        BadTimestamp,      ///< key, found: not an ISO 8601 date and time
        UnknownGeneration, ///< key, found: not "v2.3" or "v2.35"
    };
    /// What a key must hold.
    enum class ValueType { Integer, Number, Text, Object };

    Kind kind = Kind::NotJson;
    QString key; ///< dotted path from the top, e.g. "pid.iq_kp"
    ValueType expected = ValueType::Integer;
    double min = 0; ///< allowed range (Integer, Number), inclusive
    double max = 0;
    QString found;      ///< what the file holds at the key, as JSON text
    qint64 offset = -1; ///< NotJson: byte offset of the fault
    QString detail;     ///< CannotRead, TooLarge, NotJson: the reason from the system or the parser
    QString path;       ///< the file, when loaded from one
};

/// A drive's tunable parameters with the identity of the drive they came from: the file a
/// technician saves before tuning and restores afterwards (JSON, see toJson()).
struct ParameterSet {
    static constexpr int kFormatVersion = 1;
    static constexpr char kFormatName[] = "lkstudio-parameters"; ///< the "format" value
    /// A set is a few hundred bytes; load() refuses a larger file unread.
    static constexpr qint64 kMaxFileBytes = 1 << 20;

    int driveId = 1;
    QString driverName;
    QString motorName;
    std::optional<protocol::Series> series;
    double hardwareVersion = 0; ///< as shown (V2.3: raw / 10)
    double firmwareVersion = 0;
    QDateTime savedAt; ///< UTC
    /// The protocol generation of the drive: decides which gains the file holds. A file
    /// without "generation" (saved before V2.35 support) is V2.3.
    protocol::Generation generation = protocol::Generation::V2_3;
    protocol::PidGains pid;          ///< V2.3: Kp/Ki 0..255 (0x30)
    std::optional<qint32> accelDps2; ///< V2.3: nullopt when the drive did not answer read_accel
    /// V2.35: angle, speed and current loop Kp, Ki, Kd, 0..65535 each (ParamIDs 0x96..0x98).
    std::array<quint16, 9> pidV235{};

    /// {"format":"lkstudio-parameters","version":1,"saved_at":...,"generation":"v2.3",
    ///  "drive":{...},"pid":{"angle_kp":...},"accel_dps2":...}; field names follow CLI.md.
    /// V2.35 files have "generation":"v2.35", Kd keys ("angle_kd") and no "accel_dps2".
    QJsonObject toJson() const;
    QByteArray toJsonBytes() const; ///< indented, UTF-8

    /// Reads a document written by toJson(). Anything missing, unknown, given twice, of the
    /// wrong type or out of range is refused (nullopt) with `error` naming the key and range.
    static std::optional<ParameterSet> fromJson(const QByteArray &bytes,
                                                ParameterFileError *error = nullptr);

    /// Writes the file atomically (system::AtomicFile): the path holds either the whole new file or
    /// what it held before. Returns an error text, empty on success.
    QString save(const QString &path) const;
    /// Reads a file; nullopt with `error` set when it cannot be read or is not a valid set.
    static std::optional<ParameterSet> load(const QString &path,
                                            ParameterFileError *error = nullptr);
};

/// Writes `bytes` to `path` atomically (system::AtomicFile). Returns an error text, empty on
/// success.
QString writeFileAtomically(const QString &path, const QByteArray &bytes);

} // namespace lk::record
