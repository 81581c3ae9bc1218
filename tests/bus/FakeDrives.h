#pragma once

#include <protocol/Frame.h>
#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QMap>
#include <QtCore/QString>

namespace lk::bustest {

/// A table of scripted drives that answer request frames the way real ones do: read_model
/// with a model name, state reads with fixed values, echoes for echo commands, and silence
/// for commands their series lacks (0x9D and 0xA1 on MS) or for IDs not in the table.
class FakeDrives {
public:
    void add(int id, protocol::Series series);
    void remove(int id) { m_drives.remove(id); }
    bool contains(int id) const { return m_drives.contains(id); }
    /// The reply bytes for a request frame; empty for silence.
    QByteArray reply(const protocol::Frame &request) const;
    /// "MF4015" style model name used for a series.
    static QString modelName(protocol::Series series);

private:
    QMap<int, protocol::Series> m_drives;
};

} // namespace lk::bustest
