#pragma once

#include "DriveSnapshot.h"

#include <record/ParameterSet.h>

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::fleet {

/// The parameters of several drives of one bus, as read: the file a technician saves before
/// touching a machine and restores or clones from (docs/BACKUP.md). A drive whose read
/// failed is listed as failed, with what was known of it and no values.
struct BackupFile {
    /// 2: drives on CAN ("link", the "identity" declared); a file without one is written as 1.
    static constexpr int kFormatVersion = 2;
    static constexpr char kFormatName[] = "lkstudio-bus-backup"; ///< the "format" value
    /// 32 drives are a few tens of KiB; load() refuses a larger file unread.
    static constexpr qint64 kMaxFileBytes = 4 << 20;

    QDateTime savedAt;             ///< UTC
    QVector<DriveSnapshot> drives; ///< by ID, each ID once

    /// The entry of drive `id`, or nullptr.
    const DriveSnapshot *drive(int id) const;

    QJsonObject toJson() const;
    QByteArray toJsonBytes() const; ///< indented, UTF-8
    /// Reads a document written by toJson(). Anything missing, unknown, given twice, of the
    /// wrong type, out of the generation's range, or a read drive without every parameter of
    /// its generation is refused (nullopt) with `error` naming the key.
    static std::optional<BackupFile> fromJson(const QByteArray &bytes,
                                              record::ParameterFileError *error = nullptr);
    /// Writes atomically; an error text, empty on success.
    QString save(const QString &path) const;
    static std::optional<BackupFile> load(const QString &path,
                                          record::ParameterFileError *error = nullptr);
    /// One English sentence (translatable) for a refusal, naming the key.
    static QString errorText(const record::ParameterFileError &error);
};

} // namespace lk::fleet
