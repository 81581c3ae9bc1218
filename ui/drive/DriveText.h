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
/// returns typed reasons (LimitKind, FieldError, RequestStatus), the UI words them.
class DriveText {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::DriveText)
public:
    /// Which limit stopped a command, with both numbers; empty when it was allowed.
    static QString verdict(const safety::Verdict &verdict, std::optional<protocol::Series> series);
    /// A builder's refusal: the field and its allowed range.
    static QString fieldError(const protocol::FieldError &error);
    /// Why a request did not complete (timeout, disconnected, ...); empty when it did.
    static QString failure(const bus::RequestResult &result);
    /// Why a setpoint stream stopped; a refusal says which limit or field, like verdict().
    static QString setpointStop(const bus::SetpointStop &stop,
                                std::optional<protocol::Series> series);
    /// "write_pid_rom (0x32)".
    static QString command(protocol::Command command);
    /// "MF" or "unknown series".
    static QString series(std::optional<protocol::Series> series);
};

} // namespace lk::ui
