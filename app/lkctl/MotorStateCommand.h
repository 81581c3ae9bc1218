#pragma once

#include "LiveCommand.h"

#include <protocol/Command.h>
#include <protocol/Series.h>

#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// `lkctl off|stop|run ID|all`: motor_off, motor_stop or motor_run. `off all` is the
/// emergency stop (motor off to every ID 1..32 ahead of anything else); `stop all` and
/// `run all` reach every drive a quick scan finds.
class MotorStateCommand : public LiveCommand {
public:
    explicit MotorStateCommand(protocol::Command command);

    QString name() const override;
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    int runAll(LiveBus &bus, bool json);
    int runOne(LiveBus &bus, int id, bool json);
    bool allowed(LiveBus &bus, int id, std::optional<protocol::Series> series);
    void print(Console &console, bool json, const QVector<int> &acknowledged,
               const QVector<int> &silent) const;

    protocol::Command m_command;
};

} // namespace lk::lkctl
