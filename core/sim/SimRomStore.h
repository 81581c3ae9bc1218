#pragma once

#include "SimParams.h"
#include "protocol/Series.h"
#include "protocol/Values.h"

#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace lk::sim {

/// The part of a drive's memory that survives a power cycle.
struct SimRom {
    protocol::PidGains pid{100, 100, 50, 40, 50, 50};
    qint32 accelDps2 = 20000;
    quint16 encoderZero = 0; ///< written by 0x19, becomes the encoder offset at power-on
    SimParams params;        ///< V2.35 drives: the parameter table written by 0x44

    bool operator==(const SimRom &o) const
    {
        return pid == o.pid && accelDps2 == o.accelDps2 && encoderZero == o.encoderZero &&
               params == o.params;
    }
    bool operator!=(const SimRom &o) const { return !(*this == o); }
};

/// Persists simulated drives' ROM as one JSON file per ID ("rom-id03.json") in a directory.
///
/// Loads every file on construction. A file that cannot be read or parsed is reported in
/// errors() and ignored (the drive starts with defaults); nothing here throws or crashes.
/// With an empty directory nothing is persisted and the store only remembers in memory.
class SimRomStore {
public:
    explicit SimRomStore(const QString &directory = {});

    QString directory() const { return m_dir; }
    bool persistent() const { return !m_dir.isEmpty(); }

    /// The stored ROM of an ID, if any was loaded or saved for a drive of this series. A file
    /// written by a drive of another series is reported and not used.
    std::optional<SimRom> rom(int id, protocol::Series series);
    /// Remember and write to disk (atomically). False, with an entry in errors(), on failure.
    bool save(int id, protocol::Series series, const SimRom &rom);

    /// Every problem met so far, one English sentence each, oldest first.
    QStringList errors() const { return m_errors; }
    QString filePath(int id) const;

private:
    struct Entry {
        protocol::Series series;
        SimRom rom;
    };
    void loadAll();
    void loadFile(const QString &path, int id);
    void addError(const QString &message);

    QString m_dir;
    QMap<int, Entry> m_entries;
    QStringList m_errors;
};

} // namespace lk::sim
