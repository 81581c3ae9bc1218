#pragma once

#include "LiveBus.h"
#include "LiveCommand.h"

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QPair>

namespace lk::lkctl {

/// `lkctl info ID`: model, state 1 (temperature, voltage, errors), PID gains, acceleration
/// (V2.3) or gains and the drive's parameter table (V2.35).
class InfoCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("info"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// `parts`: the reply fields of state1, pid and accel (those that answered), by key.
    void print(Console &console, int id, const LiveBus::Identity &who,
               const QList<QPair<QString, QJsonObject>> &parts, bool json) const;
    /// Send `request`, add its reply's fields to `into`; false (reported) when it failed.
    static bool readInto(LiveBus &bus, const protocol::Request &request, QJsonObject &into);
    static bool readV23(LiveBus &bus, int id, QList<QPair<QString, QJsonObject>> &parts);
    static bool readV235(LiveBus &bus, int id, QList<QPair<QString, QJsonObject>> &parts);
};

} // namespace lk::lkctl
