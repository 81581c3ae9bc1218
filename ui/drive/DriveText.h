#pragma once

#include <bus/RequestResult.h>
#include <bus/SetpointStop.h>
#include <protocol/FieldError.h>
#include <protocol/Series.h>
#include <safety/MotionGuard.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// Translated sentences the drive views show for refusals and failed requests: the core
/// returns typed reasons (FieldError, RequestStatus), the UI words them (a safety verdict:
/// text::VerdictText, shared with lkctl).
class DriveText {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::DriveText)
public:
    /// A builder's refusal: the field and its allowed range.
    static QString fieldError(const protocol::FieldError &error);
    /// Why a request did not complete (timeout, disconnected, ...); empty when it did.
    static QString failure(const bus::RequestResult &result);
    /// failure() of a command that can move a motor: when it went out but its reply was lost
    /// or corrupt (fw 2.35 spoils ~1 % of 0xA4 checksums), the drive may have acted on it,
    /// and the text says so.
    static QString motionFailure(const bus::RequestResult &result);
    /// The safety gate's refusal, framed: "Refused: <which limit, both numbers>."
    static QString refusal(const safety::Verdict &verdict, std::optional<protocol::Series> series);
    /// Why a setpoint stream stopped; a refusal says which limit or field, like refusal().
    static QString setpointStop(const bus::SetpointStop &stop,
                                std::optional<protocol::Series> series);
    /// Why motion stopped, for every reason but a refusal (which setpointStop() words with
    /// its limit); the control view says the same when it halts for that reason.
    static QString stopReason(bus::SetpointStopReason reason);
    /// "write_pid_rom (0x32)".
    static QString command(protocol::Command command);
    /// "MF" or "unknown series" (VerdictText's).
    static QString series(std::optional<protocol::Series> series);
};

} // namespace lk::ui
