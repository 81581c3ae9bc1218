#pragma once

#include "LiveCommand.h"
#include "MonitorTable.h"

#include <bus/BusStatistics.h>
#include <protocol/Command.h>

#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// `lkctl monitor ID...`: poll drives and stream their values one poll round at a time, as
/// CSV (wide or long, docs/CSV.md) or JSON lines, until interrupted (SIGINT/SIGTERM), --duration or
/// --count; then the achieved rate and the bus statistics on standard error.
class MonitorCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("monitor"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

    static constexpr double kDefaultRateHz = 10;
    /// Without a reply from any drive for this long (or three poll periods and a second, if
    /// longer), monitoring ends with status 1.
    static constexpr double kSilenceS = 5;

private:
    struct Plan {
        QVector<int> ids;
        QVector<protocol::Command> commands;
        double rateHz = kDefaultRateHz;
        std::optional<double> durationS;
        std::optional<qint64> count;
        MonitorFormat format = MonitorFormat::CsvWide;
        bool simulated = false;  ///< --sim: no wire time, so no bus limit to compare with
        QString linkRate;        ///< "115200 baud", "1000000 bit/s on CAN"
        double turnaroundMs = 0; ///< the most a drive may take to answer on this link
        /// Transactions/s for this mix (LinkTiming): the wire time alone (no rate can pass
        /// it), and with the turnaround a drive may take (a rate can pass that one).
        double wireLimit = 0;
        double slowDriveLimit = 0;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    /// --csv, --csv-layout and --json; nullopt with `error` set when they conflict.
    static std::optional<MonitorFormat> parseFormat(const ArgParser &parser, QString *error);
    /// Why the plan cannot be polled: a --what set no drive's series has, or a drive whose
    /// series has none of them (MS has no read_state3), naming the drive, the series, the
    /// command and the set; empty when fine.
    static QString lackingSet(const Plan &plan,
                              const QMap<int, std::optional<protocol::Series>> &series);
    static double silenceLimitS(const Plan &plan);
    /// Poll until a stop condition; returns the exit status.
    int stream(LiveBus &bus, const Plan &plan, MonitorTable &table);
    void report(LiveBus &bus, const Plan &plan, const MonitorTable &table, qint64 rows,
                qint64 samples, double samplesSpanS, const bus::BusStatistics &stats) const;
};

} // namespace lk::lkctl
