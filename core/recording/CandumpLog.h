#pragma once

#include "RecordingFormat.h"

#include <protocol/CanRecord.h>

#include <QtCore/QByteArray>
#include <QtCore/QIODevice>

#include <functional>
#include <optional>

namespace lk::recording {

class RecordingReader;

/// candump logs (can-utils), which can-utils, python-can and SavvyCAN read: a CAN recording
/// written as `candump -L` lines ("(1700000000.123456) can0 141#9C00000000000000", error
/// frames with the CAN_ERR_FLAG in their 8-digit ID), and a candump log (that form, or
/// candump's default "can0  141   [8]  9C 00 ..." with or without a "(time)") read back as a
/// recording of received frames, so that every reader of recordings reads it.
class CandumpLog {
public:
    /// The interface a CAN recording names ("socketcan:can0 @ 1000000" -> "can0"), else "can0".
    static QString interfaceOf(const RecordingHeader &header);
    /// Writes every frame of the CAN recording `reader` opened, in order, at its wall-clock
    /// time: what the tool sent, and what it received but for its own frames looped back
    /// (those are the same frames). Returns the frames written; -1 for a recording not made
    /// on CAN (nothing written).
    static qint64 write(RecordingReader &reader, QIODevice &out);
    /// Calls `frame` for every CAN frame of a CAN recording, in order, with its session time:
    /// what the tool sent, and what it received but for its own frames looped back.
    static void forEachFrame(RecordingReader &reader,
                             const std::function<void(qint64, const protocol::CanRecord &)> &frame);
    /// One line of a candump log; nullopt for anything else.
    static std::optional<protocol::CanRecord> parseLine(const QString &line);
    /// Whether `text` starts like a candump log (its first non-empty line parses).
    static bool looksLikeLog(const QByteArray &text);
    /// A candump log as the bytes of a recording (LinkKind::Can, every frame received, the
    /// session clock from the first frame's time). nullopt with `badLine` (from 1) set at the
    /// first line that is no frame; empty lines are skipped.
    static std::optional<QByteArray> toRecording(const QByteArray &text, int *badLine);
};

} // namespace lk::recording
