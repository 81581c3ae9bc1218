#pragma once

#include <bus/KnownMotor.h>
#include <protocol/Command.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// Whether a drive's protocol generation has a command, and if not, the sentence that says so
/// (the drive views show it in place of the controls; nothing is sent). The same rule as the
/// bus thread's refusal (MotorRegistry::unavailableReason): on RS485 the generation counts once
/// the model was read; on CAN, which has no model read, once it was chosen or told by a reply,
/// and the link decides as much as the generation (docs/CAN.md section 3).
class GenerationNote {
    Q_DECLARE_TR_FUNCTIONS(GenerationNote)
public:
    /// The drive's generation as far as it is known on `link`; nullopt while it is not.
    static std::optional<protocol::Generation>
    generationOf(const bus::KnownMotor &motor, protocol::Link link = protocol::Link::Rs485);
    /// Empty when the drive has `command` on `link`; else why it is absent. `what` names the
    /// function ("brake control").
    static QString absence(const bus::KnownMotor &motor, protocol::Command command,
                           const QString &what, protocol::Link link = protocol::Link::Rs485);
};

} // namespace lk::ui
