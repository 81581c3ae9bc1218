#pragma once

#include "protocol/Command.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace lk::sim {

/// What lksim's simulated foreign master does (`--controller SPEC`, docs/CLI.md "lksim").
///
/// SPEC is comma-separated KEY=VALUE, every key optional, each at most once; a value's parts
/// are separated by ':':
///   rate=HZ|max            requests per second on the bus (default 100); max: back to back
///   ids=LIST               the drives it talks to, "1-4:17" (default: every drive on the bus)
///   poll=LIST|none         reads it polls from each drive per round, codes or names,
///                          "9c:9a:read_multi_turn" (default 9c); reads only
///   speed=sine:AdpS:FHz    a speed setpoint (0xA2) per drive and round, A*sin(2*pi*F*t)
///   move=every:Ts[:Xdeg][:Vdps]  every T seconds each drive gets an incremental move
///                          (0xA8) of +X, then -X next time (default 90 deg at 360 dps)
///   timeout=Nms            how long it waits for a reply that does not come (default 5 ms)
/// A bad spec is refused with the key named.
struct ControllerSpec {
    struct Sine {
        double amplitudeDps = 0;
        double frequencyHz = 0;
    };
    struct Move {
        double periodS = 0;
        double stepDeg = 90;
        double maxSpeedDps = 360;
    };

    double rateHz = 100; ///< 0: as fast as the bus allows
    QList<int> ids;      ///< empty: every drive on the bus, ascending
    QList<protocol::Command> poll{protocol::Command::ReadState2}; ///< per drive and round
    std::optional<Sine> speed;
    std::optional<Move> move;
    double timeoutS = 0.005;

    /// nullopt with one sentence naming the key in `error`.
    static std::optional<ControllerSpec> parse(const QString &text, QString *error = nullptr);
    /// Back to the syntax, every key written ("rate=100,ids=1-4,poll=9c,timeout=5ms").
    QString toString() const;
    /// The commands a foreign master may poll: the reads without data (read_state2, ...).
    static bool isPollable(protocol::Command command);
};

} // namespace lk::sim
