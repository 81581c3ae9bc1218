#pragma once

#include <fleet/BackupFile.h>
#include <fleet/FleetRestore.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

class Console;
class LiveBus;

/// What backup, diff, restore and clone share: reading drives on a LiveBus, ID lists and maps,
/// and their JSON.
class FleetBus {
public:
    /// The IDs of the drives that answer a scan of 1..32 (for "all").
    static QVector<int> scanIds(LiveBus &bus);
    /// Reads every parameter of `ids`, one drive after another.
    static QVector<fleet::DriveSnapshot> read(LiveBus &bus, const QVector<int> &ids);

    /// The drive summary of backup's output: id, status, failure, link, identity ("read" or,
    /// on CAN, "declared"), generation, series, motor name (null unless read).
    static QJsonObject driveJson(const fleet::DriveSnapshot &d);
    /// "v2.3", "v2.35"; on CAN the words of --drives: "can", "can236".
    static QString generationText(const fleet::DriveIdentity &who);
    /// "drive N was not read: WHY", and on CAN for a drive not declared, how to declare it.
    static QString failureText(LiveBus &bus, const fleet::DriveSnapshot &d);
    /// False for a key a restore never writes (the encoder offset: each motor's own zero).
    static bool isRestorable(const fleet::DriveSnapshot &drive, const QString &key);
    /// The rows of `against` compared with `reference`; `differing` counts the restorable
    /// keys that differ or are unknown.
    static QJsonArray diffJson(const fleet::DriveSnapshot &reference,
                               const fleet::DriveSnapshot &against, int *differing);
    /// A value as text: the number, or "unknown".
    static QString valueText(const std::optional<qint64> &v);
    /// The backup file `path`, or nullopt after printing why (naming the key).
    static std::optional<fleet::BackupFile> loadBackup(Console &console, const QString &command,
                                                       const QString &path);
};

} // namespace lk::lkctl
