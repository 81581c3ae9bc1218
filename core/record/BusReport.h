#pragma once

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
struct BusReportDrive {
    int id = 1;
    std::optional<protocol::Series> series;
    std::optional<protocol::ModelInfo> model;
    std::optional<protocol::PidGains> pid;
    std::optional<qint32> accelDps2;
    std::optional<protocol::State1> state1;
    QStringList problems; ///< one English line per read that failed, e.g. "read_pid: timeout"
    bool answered() const { return model || pid || accelDps2 || state1; }
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
