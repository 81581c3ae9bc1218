#pragma once

#include <bus/KnownMotor.h>
#include <protocol/Command.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// Whether a drive's protocol generation has a command, and if not, the sentence that says so
/// (the drive views show it in place of the controls; nothing is sent).
class GenerationNote {
    Q_DECLARE_TR_FUNCTIONS(GenerationNote)
public:
    /// The generation from the drive's model reply; nullopt while the model was not read.
    static std::optional<protocol::Generation> generationOf(const bus::KnownMotor &motor);
    /// Empty when the drive's generation has `command`; else why it is absent. `what` names
    /// the function ("brake control").
    static QString absence(const bus::KnownMotor &motor, protocol::Command command,
                           const QString &what);
};

} // namespace lk::ui
