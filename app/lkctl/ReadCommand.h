#pragma once

#include "LiveCommand.h"

#include <protocol/Command.h>

#include <optional>

namespace lk::lkctl {

/// `lkctl read ID WHAT`: one read command (pid, accel, encoder, multi-turn, single-turn,
/// state1, state2, state3, model), as text or as CLI.md JSON.
class ReadCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("read"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

    /// "state2" -> read_state2; nullopt for anything else.
    static std::optional<protocol::Command> commandFor(const QString &what);
};

} // namespace lk::lkctl
