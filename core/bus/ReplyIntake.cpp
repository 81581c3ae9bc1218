#include "ReplyIntake.h"

namespace lk::bus {

using protocol::Command;
using protocol::CommandTable;

namespace {
bool movesMotor(Command c)
{
    return CommandTable::info(c).movesMotor;
}

/// The generation a reply to `command` proves: a command only one generation has.
std::optional<protocol::Generation> generationOf(Command command)
{
    const quint8 on = CommandTable::info(command).generations;
    if (on == protocol::kOnV23)
        return protocol::Generation::V2_3;
    if (on == protocol::kOnV235)
        return protocol::Generation::V2_35;
    return std::nullopt;
}
} // namespace

std::optional<TelemetrySample> ReplyIntake::take(const protocol::Reply &reply, double time,
                                                 const Asked &asked, bool &motorsChanged)
{
    bool changed = m_motors.noteSeen(reply.id);
    // A model reply tells the drive's generation (and the series its names give), whoever
    // asked for it (a scan, lkctl info, the drive-info view, another master): later replies
    // from it are decoded with its layouts. Without one, a command only one generation has
    // tells the generation.
    if (const auto *model = std::get_if<protocol::ModelInfo>(&reply.payload))
        changed = m_motors.learnModel(reply.id, *model, std::nullopt) || changed;
    else if (const std::optional<protocol::Generation> g = generationOf(reply.command))
        changed = m_motors.learnGeneration(reply.id, *g) || changed;
    motorsChanged = motorsChanged || changed;
    const bool halt = asked.command == Command::MotorOff || asked.command == Command::MotorStop;
    if (movesMotor(asked.command) || halt)
        m_motors.noteMotion(reply.id, !halt); // the emergency stop reaches it first
    // A scan's probe comes before read_model has told the drive's layouts (a V2.35 drive's
    // 24 V read as 0.90 V with V2.3's): the scan re-reads it for its result, telemetry skips it.
    if (asked.scanProbe && !m_motors.all().value(reply.id).model.has_value())
        return std::nullopt;
    std::optional<TelemetrySample> s = TelemetrySample::fromReply(reply, time);
    if (!s)
        return std::nullopt;
    if (!movesMotor(asked.command) && s->has(TelemetryField::Speed))
        m_motors.noteMotion(reply.id, s->speedDps != 0);
    s->cycle = asked.pollCycle; // which poll round it answers: rows are built per round
    s->cycleTime = asked.pollCycleStart;
    m_telemetry.add(*s);
    return s;
}

} // namespace lk::bus
