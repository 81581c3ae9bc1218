#pragma once

#include "LiveCommand.h"
#include "MonitorTable.h"

#include <bus/ListenStatistics.h>
#include <protocol/Series.h>

#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

class LiveBus;
class ListenTable;

/// `lkctl listen`: watch a bus another master drives, transmitting nothing. The port opens
/// read-only (RTS and DTR cleared where the driver allows), the session runs listen-only
/// (bus::LinkMode::ListenOnly), and what the master and its drives say is decoded: the
/// drives' replies and the master's commanded values as rows in `lkctl monitor`'s long
/// layout (CSV or JSON lines), until interrupted or --duration; then what the master did
/// (requests/s, unanswered requests, reply latency, checksum errors, bus load) on standard
/// error.
class ListenCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("listen"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// A drive the user names (--drives): its series, until a model reply tells.
    struct Drive {
        int id = 0;
        protocol::Series series = protocol::Series::MF;
    };
    struct Plan {
        std::optional<double> durationS;
        MonitorFormat format = MonitorFormat::CsvLong;
        QVector<Drive> drives;
    };
    /// "3:MG,17:MS" -> drives; nullopt with `error` naming the item.
    static std::optional<QVector<Drive>> parseDrives(const QString &text, QString *error);
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    /// Print rows until a stop condition; returns the exit status.
    int stream(LiveBus &bus, const Plan &plan, ListenTable &table);
    static void report(LiveBus &bus, qint64 rows, const bus::ListenStatistics &stats);
};

} // namespace lk::lkctl
