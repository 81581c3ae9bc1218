#pragma once

#include "LiveBus.h"
#include "LiveCommand.h"

#include <QtCore/QJsonObject>

#include <protocol/Command.h>

#include <optional>

namespace lk::lkctl {

/// `lkctl read ID WHAT`: one read command (pid, accel, encoder, multi-turn, single-turn,
/// state1, state2, state3, model, params), as text or as CLI.md JSON.
class ReadCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("read"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

    /// "state2" -> read_state2; nullopt for anything else.
    static std::optional<protocol::Command> commandFor(const QString &what);
    /// A CAN V2.36 drive's gains and limits from its control parameters (0xC0), under the
    /// V2.35 field names: the three PIDs (`gains`), the input limits and ramps (`limits`).
    /// False after printing why.
    static bool readCan236Params(LiveBus &bus, int id, bool gains, bool limits,
                                 QJsonObject &fields);

private:
    static bool readInto(LiveBus &bus, protocol::Command command, int id, QJsonObject &fields);
    /// `pid` (gainsOnly) or `params` on a V2.35 drive, with read_param.
    static bool readV235Params(LiveBus &bus, int id, bool gainsOnly, QJsonObject &fields);
};

} // namespace lk::lkctl
