#pragma once

#include <protocol/Series.h>
#include <protocol/Values.h>

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QString>

#include <optional>

namespace lk::record {

/// A drive's tunable parameters with the identity of the drive they came from: the file a
/// technician saves before tuning and restores afterwards (JSON, see toJson()).
struct ParameterSet {
    static constexpr int kFormatVersion = 1;

    int driveId = 1;
    QString driverName;
    QString motorName;
    std::optional<protocol::Series> series;
    double hardwareVersion = 0; ///< as shown (V2.3: raw / 10)
    double firmwareVersion = 0;
    QDateTime savedAt; ///< UTC
    protocol::PidGains pid;
    std::optional<qint32> accelDps2; ///< nullopt when the drive did not answer read_accel

    /// {"format":"lkstudio-parameters","version":1,"saved_at":...,"drive":{...},
    ///  "pid":{"angle_kp":...},"accel_dps2":...}; field names follow CLI.md.
    QJsonObject toJson() const;
    QByteArray toJsonBytes() const; ///< indented, UTF-8

    /// Reads a document written by toJson(). Anything missing, of the wrong type or out of
    /// range is refused (nullopt) with one English sentence naming the field in `error`.
    static std::optional<ParameterSet> fromJson(const QByteArray &bytes, QString *error = nullptr);

    /// Writes the file atomically (QSaveFile): the path holds either the whole new file or
    /// what it held before. Returns an error text, empty on success.
    QString save(const QString &path) const;
    /// Reads a file; nullopt with `error` set when it cannot be read or is not a valid set.
    static std::optional<ParameterSet> load(const QString &path, QString *error = nullptr);
};

/// Writes `bytes` to `path` atomically (QSaveFile). Returns an error text, empty on success.
QString writeFileAtomically(const QString &path, const QByteArray &bytes);

} // namespace lk::record
