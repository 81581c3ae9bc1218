#pragma once

#include "MonitorTable.h"

#include <bus/TelemetrySample.h>
#include <record/TelemetryCsv.h>

#include <QtCore/QByteArray>
#include <QtCore/QList>

namespace lk::lkctl {

/// What `lkctl listen` prints: one row per sample observed on a bus another master drives (a
/// drive's reply, or a value the master commanded), in the long layout of `lkctl monitor`
/// (docs/CSV.md): CSV time_s,id, then every telemetry column; or JSON lines with the same
/// keys, only those the sample has. time_s is when the frame arrived (host clock, seconds
/// since the port opened). Nobody polls in rounds here, and which drives talk is not known
/// beforehand: there is no wide layout.
class ListenTable {
public:
    explicit ListenTable(MonitorFormat format);

    /// The CSV header line (empty for JSON), newline included.
    QByteArray header() const;
    /// The row of one sample, newline included.
    QList<QByteArray> add(const bus::TelemetrySample &sample);

private:
    MonitorFormat m_format;
    record::TelemetryCsv m_csv;
};

} // namespace lk::lkctl
