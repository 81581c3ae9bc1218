#pragma once

#include <bus/LinkMode.h>
#include <bus/TransportFactory.h>

#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

class ArgParser;

/// Which bus a live subcommand talks to: a serial port (`--port DEV --baud N`) or the
/// in-process simulator (`--sim ID:SERIES,...`, optionally `--sim-rom-dir DIR`).
struct BusOptions {
    /// Environment variables for the defaults of --port and --baud (the command line wins).
    static constexpr const char *kPortVariable = "LKCTL_PORT";
    static constexpr const char *kBaudVariable = "LKCTL_BAUD";

    QString port;
    int baud = 115200;
    QString simSpec;   ///< non-empty: the in-process simulated bus
    QString simRomDir; ///< where the simulated drives keep their ROM (empty: memory only)
    /// ListenOnly (`lkctl listen`): the port opens read-only and the session sends nothing.
    bus::LinkMode mode = bus::LinkMode::Active;

    /// Declare --port, --baud, --sim and --sim-rom-dir on a parser.
    static void declare(ArgParser &parser);
    /// Read them back, with LKCTL_PORT and LKCTL_BAUD filling in what the command line leaves
    /// out; nullopt with `error` when unusable (no bus, both --port and --sim, a baud that
    /// is not one of the nine, naming --baud or LKCTL_BAUD, a bad --sim spec).
    static std::optional<BusOptions> from(const ArgParser &parser, QString *error);

    bool isSimulated() const { return !simSpec.isEmpty(); }
    /// The port as a device path: a bare name stays (the transport looks in /dev), a name
    /// with a slash is a path, made absolute against the working directory ("./bus").
    static QString portPath(const QString &port);
    bus::TransportFactory factory() const;
    /// The text of `lkctl CMD --help` that documents these options.
    static QString helpText();
};

} // namespace lk::lkctl
