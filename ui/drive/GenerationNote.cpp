#include "GenerationNote.h"

#include <protocol/Series.h>

namespace lk::ui {

std::optional<protocol::Generation> GenerationNote::generationOf(const bus::KnownMotor &motor)
{
    return motor.model ? std::optional(motor.model->generation) : std::nullopt;
}

QString GenerationNote::absence(const bus::KnownMotor &motor, protocol::Command command,
                                const QString &what)
{
    const QString code = QLatin1String("0x") + QString::number(int(command), 16).toUpper();
    const auto generation = generationOf(motor);
    if (!generation)
        return tr("The protocol generation of this drive is not known (its model was not read), "
                  "so %1 (%2), a V2.35 command, is not offered. Nothing is sent.")
            .arg(what, code);
    if (protocol::CommandTable::availableOn(command, *generation))
        return {};
    return tr("This drive speaks protocol %1, which has no %2 command (%3): it came with V2.35 "
              "(firmware 2.35 and later). Nothing is sent.")
        .arg(protocol::generationName(*generation), what, code);
}

} // namespace lk::ui
