#pragma once

#include "BusStatistics.h"

#include <QtCore/QMap>
#include <QtCore/QMetaType>

namespace lk::bus {

/// One drive as another master's traffic shows it (ListenStatistics::perDrive).
struct ListenDriveStatistics {
    quint64 requests = 0;         ///< requests the other master sent it
    quint64 replies = 0;          ///< its replies, paired or not
    quint64 unanswered = 0;       ///< its requests that got no reply (the other master's timeouts)
    double requestsPerSecond = 0; ///< over the last period
    /// Request to reply, of paired replies. Approximate: both are stamped when their chunk
    /// arrived, after the adapter's latency timer (up to 16 ms on FTDI without the udev rule).
    LatencySummary latency;
};

/// One command of the other master's (ListenStatistics::perCommand).
struct ListenCommandStatistics {
    quint64 requests = 0;
    double requestsPerSecond = 0; ///< over the last period
};

/// What a listen-only session saw another master do (BusSession::listenStatisticsUpdated,
/// at BusConfig::statisticsHz). Counters only grow during a session; rates are over the last
/// period (`periodS`).
struct ListenStatistics {
    double time = 0;    ///< seconds since the session started
    double periodS = 0; ///< the period the rates cover
    int baud = 0;
    quint64 requests = 0;
    quint64 replies = 0;
    quint64 paired = 0;         ///< replies matched with their request
    quint64 unanswered = 0;     ///< requests without a reply (the other master's timeouts)
    quint64 orphanReplies = 0;  ///< replies whose request was not seen
    quint64 ambiguous = 0;      ///< echo frames that could be a request or a reply: not guessed
    quint64 corruptReplies = 0; ///< replies with a bad data checksum
    quint64 brokenPairs = 0;    ///< requests left unpaired because bytes were lost meanwhile
    quint64 checksumErrors = 0; ///< bad header or data checksums
    quint64 garbageBytes = 0;   ///< bytes skipped while resynchronising
    quint64 bytes = 0;          ///< every byte seen (on CAN: of the transport's records)
    quint64 canErrorFrames = 0; ///< CAN error frames (bus errors, not faults of a frame)
    quint64 otherFrames = 0;    ///< CAN frames on IDs that are no drive's (0x280 included)
    double requestsPerSecond = 0;
    /// The share of the wire's capacity the bytes of the last period took (10 bits a byte at
    /// the baud; on CAN the bits of an 8-byte frame, unstuffed, at the bit rate): 1.0 is a
    /// saturated bus.
    double busLoad = 0;
    QMap<int, ListenDriveStatistics> perDrive;
    QMap<quint8, ListenCommandStatistics> perCommand; ///< by command code
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::ListenStatistics)
