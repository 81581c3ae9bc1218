#include "GenerationNote.h"

#include <protocol/Series.h>

namespace lk::ui {

std::optional<protocol::Generation> GenerationNote::generationOf(const bus::KnownMotor &motor,
                                                                 protocol::Link link)
{
    if (motor.model)
        return motor.model->generation;
    // CAN has no model read: the user's choice or the replies (reply ID, 0x9A layout) tell it.
    if (link == protocol::Link::Can && motor.generationKnown())
        return motor.generation;
    return std::nullopt;
}

QString GenerationNote::absence(const bus::KnownMotor &motor, protocol::Command command,
                                const QString &what, protocol::Link link)
{
    const QString code = QLatin1String("0x") + QString::number(int(command), 16).toUpper();
    const auto generation = generationOf(motor, link);
    if (link == protocol::Link::Can) {
        if (!generation)
            return tr("The protocol generation of this drive is not known yet (CAN has no model "
                      "read: choose it, or wait for its replies), so %1 (%2) is not offered. "
                      "Nothing is sent.")
                .arg(what, code);
        protocol::DecodeContext context;
        context.link = link;
        context.generation = *generation;
        context.series = motor.series.value_or(protocol::Series::MF);
        if (protocol::CommandTable::availableOn(command, context))
            return {};
        return tr("This drive speaks %1, which has no %2 command (%3). Nothing is sent.")
            .arg(protocol::dialectName(context), what, code);
    }
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
