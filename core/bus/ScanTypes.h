#pragma once

#include "LinkMode.h"

#include <protocol/Series.h>
#include <protocol/Values.h>

#include <QtCore/QMetaType>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {

/// What to scan. IDs and bauds are checked (1..32, the nine LK bauds).
struct ScanOptions {
    int firstId = 1;
    int lastId = 32;
    bool sweepBauds = false; ///< reopen the transport at each baud in `bauds`
    QVector<int> bauds;      ///< empty: all nine LK bauds, fastest last
    /// Silent IDs are probed again after the fast first pass with the full adaptive timeout:
    /// always when retries > 0 (with retries - 1 extra attempts each), and with 0 only when
    /// the first pass heard a late reply (the link is slower than assumed). A corrupt reply
    /// (someone is there) is always probed again at once, up to twice.
    int retries = 0;
    /// Keep the read_state1 probe's answer in FoundMotor::state1 (the probe is sent anyway).
    bool readState = true;
};

/// Where a scan is (BusSession::scanProgress), after each probed ID.
struct ScanProgress {
    int baud = 0;
    int id = 0;    ///< the ID just probed
    int done = 0;  ///< probes finished, over all bauds
    int total = 0; ///< probes planned, over all bauds
    int found = 0; ///< drives found so far
};

/// A drive that answered the scan's probe (read_state1), with its model when read_model
/// answered too.
struct FoundMotor {
    int id = 0;
    int baud = 0;
    protocol::ModelInfo model;
    bool modelKnown = false;                ///< read_model answered; otherwise `model` is empty
    std::optional<protocol::Series> series; ///< inferred from the model names; nullopt: unknown
    std::optional<protocol::State1> state1; ///< from read_state1, when it answered
    /// CAN: the generation the reply told (its ID or 0x9A layout) or the user chose; nullopt
    /// when neither says (RS485: the model's, when read).
    std::optional<protocol::Generation> generation;
    protocol::Link link = protocol::Link::Rs485; ///< the link it was found on
};

/// The end of a scan (BusSession::scanFinished); always emitted once per scan().
struct ScanSummary {
    QVector<FoundMotor> motors; ///< ascending baud then ID
    bool cancelled = false;
    QString error; ///< why the scan could not run or stopped (empty when it ran)
    SendRefusal refusal = SendRefusal::None; ///< ListenOnly: not run, nothing sent

    /// The scan a listen-only session refused: it did not run and sent nothing.
    static ScanSummary refusedListenOnly(int baud)
    {
        ScanSummary s;
        s.error = listenOnlyReason();
        s.refusal = SendRefusal::ListenOnly;
        s.finalBaud = baud;
        return s;
    }
    int finalBaud = 0; ///< the transport's baud after the scan
    double elapsedS = 0;
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::ScanProgress)
Q_DECLARE_METATYPE(lk::bus::FoundMotor)
Q_DECLARE_METATYPE(lk::bus::ScanSummary)
