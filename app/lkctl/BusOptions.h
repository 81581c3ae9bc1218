#pragma once

#include <bus/DriveIdentity.h>
#include <bus/LinkMode.h>
#include <bus/TransportFactory.h>

#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

class ArgParser;

/// Which bus a live subcommand talks to: a serial port (`--port DEV --baud N`), a CAN
/// interface through Qt SerialBus (`--can PLUGIN:INTERFACE --bitrate N`) or the in-process
/// simulator (`--sim ID:SERIES,...`, optionally `--sim-rom-dir DIR`). `--drives` tells the
/// drives' identity where no model read can (every CAN drive).
struct BusOptions {
    /// Environment variables for the defaults of --port, --baud and --can (the command line
    /// wins).
    static constexpr const char *kPortVariable = "LKCTL_PORT";
    static constexpr const char *kBaudVariable = "LKCTL_BAUD";
    static constexpr const char *kCanVariable = "LKCTL_CAN";

    QString port;
    int baud = 115200;
    QString simSpec;       ///< non-empty: the in-process simulated bus
    QString simRomDir;     ///< where the simulated drives keep their ROM (empty: memory only)
    QString canPlugin;     ///< non-empty: a CAN link, "socketcan", "virtualcan", "peakcan"...
    QString canInterface;  ///< "can0", or for virtualcan "tcp://127.0.0.1:PORT/can0"
    int bitRate = 1000000; ///< the CAN bit rate (--bitrate)
    QVector<bus::DriveIdentity> drives; ///< --drives: the user's word on each drive
    /// ListenOnly (`lkctl listen`): the port opens read-only and the session sends nothing.
    bus::LinkMode mode = bus::LinkMode::Active;

    /// Declare --port, --baud, --sim and --sim-rom-dir on a parser.
    static void declare(ArgParser &parser);
    /// Read them back, with LKCTL_PORT and LKCTL_BAUD filling in what the command line leaves
    /// out; nullopt with `error` when unusable (no bus, both --port and --sim, a baud that
    /// is not one of the nine, naming --baud or LKCTL_BAUD, a bad --sim spec).
    /// `listenDrives`: --drives is listen's own (ID:SERIES, the generation from the replies'
    /// lengths), not a drive identity: left to the command.
    static std::optional<BusOptions> from(const ArgParser &parser, QString *error,
                                          bool listenDrives = false);

    bool isSimulated() const { return !simSpec.isEmpty(); }
    bool isCan() const { return !canPlugin.isEmpty(); }
    /// The rate the session opens at: the CAN bit rate, else the baud.
    int rate() const { return isCan() ? bitRate : baud; }
    /// The port as a device path: a bare name stays (the transport looks in /dev), a name
    /// with a slash is a path, made absolute against the working directory ("./bus").
    static QString portPath(const QString &port);
    bus::TransportFactory factory() const;
    /// The text of `lkctl CMD --help` that documents these options (without --drives for
    /// listen, which documents its own).
    static QString helpText(bool withDrives = true);
};

} // namespace lk::lkctl
