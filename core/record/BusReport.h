#pragma once

#include <protocol/Parameter.h>
#include <protocol/Series.h>
#include <protocol/Values.h>

#include <QtCore/QByteArray>
#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::record {

/// What one drive told the bus report: every part is optional because any read may fail.
/// A drive is read by its generation: V2.3 answers read_pid and read_accel, V2.35 has its
/// gains and limits in the parameter table (read_param 0x96..0x9E) instead.
struct BusReportDrive {
    int id = 1;
    std::optional<protocol::Series> series;
    /// The model's (read_model), else the one the session knew; nullopt: unknown, and then
    /// neither gains nor parameters are asked for.
    std::optional<protocol::Generation> generation;
    std::optional<protocol::ModelInfo> model;
    std::optional<protocol::PidGains> pid; ///< V2.3 (0x30)
    std::optional<qint32> accelDps2;       ///< V2.3 (0x33)
    /// V2.35: the parameters read with read_param, as they came (the gains 0x96..0x98, the
    /// limits and ramps 0x99..0x9E; the max angle is its two halves).
    QVector<protocol::ParameterValue> params;
    std::optional<protocol::State1> state1;
    QStringList problems; ///< one English line per read that failed, e.g. "read_pid: timeout"
    bool answered() const { return model || pid || accelDps2 || !params.isEmpty() || state1; }

    /// The state as a line: "33 °C, 24.37 V; over-current, stall" - the voltage at the
    /// generation's resolution (0.1 V, V2.35 0.01 V) and the set fault flags by the names of
    /// the drive's generation (translated); "–" when state1 was not read.
    QString stateText() const;
    /// The gains as a line: V2.3 "100/100 · 50/40 · 50/50" (Kp/Ki of the angle, speed and iq
    /// loops), V2.35 with Kd: "100/100/0 · 50/40/0 · 50/50/0"; "–" when none were read.
    QString gainsText() const;
    /// V2.3: the acceleration "20000 dps/s"; V2.35: the limits and ramps of the parameter
    /// table ("max torque 2000 · max speed 6000 dps · ..."); "–" when none were read.
    QString limitsText() const;
};

/// A snapshot of every drive on a bus for a service record: built by the UI from replies,
/// written as JSON (machine-readable, field names from CLI.md) and as a readable HTML page.
struct BusReport {
    static constexpr int kFormatVersion = 1;

    QDateTime createdAt; ///< UTC
    QString connection;  ///< the transport's description, e.g. "/dev/ttyUSB0 @ 115200"
    int baud = 0;
    QString toolVersion;            ///< the program that wrote the report
    QVector<BusReportDrive> drives; ///< ascending ID

    QJsonObject toJson() const;
    QByteArray toJsonBytes() const; ///< indented, UTF-8
    /// A self-contained HTML page (inline style, no scripts); headings are translatable.
    QString toHtml() const;
    /// Writes both files atomically. Returns an error text, empty when both were written.
    QString save(const QString &jsonPath, const QString &htmlPath) const;
};

} // namespace lk::record
