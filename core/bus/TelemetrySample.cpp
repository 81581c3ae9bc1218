#include "TelemetrySample.h"

#include "TelemetryFieldInfo.h"

namespace lk::bus {

namespace {
void fill(TelemetrySample &s, const protocol::State1 &v)
{
    s.temperatureC = v.temperatureC;
    s.voltageV = v.voltageV();
    s.errorState = v.errorState;
    s.fields |= TelemetryField::Temperature | TelemetryField::Voltage | TelemetryField::ErrorState;
    // V2.35 layouts only; a V2.3 reply has neither, and an undocumented state byte is no state.
    if (const std::optional<double> a = v.busCurrentA()) {
        s.busCurrentA = *a;
        s.fields |= TelemetryField::BusCurrent;
    }
    if (const std::optional<bool> on = v.motorOn()) {
        s.motorOn = *on;
        s.fields |= TelemetryField::MotorOn;
    }
}

void fill(TelemetrySample &s, const protocol::State2 &v)
{
    s.temperatureC = v.temperatureC;
    s.speedDps = v.speedDps;
    s.encoder = v.encoder;
    s.fields |= TelemetryField::Temperature | TelemetryField::Speed | TelemetryField::Encoder;
    if (v.isPower) {
        s.power = v.torqueRaw;
        s.fields |= TelemetryField::Power;
    } else {
        s.iqA = v.iqA();
        s.fields |= TelemetryField::IqA;
    }
}

void fill(TelemetrySample &s, const protocol::State3 &v)
{
    s.temperatureC = v.temperatureC;
    s.iaA = v.iaA();
    s.ibA = v.ibA();
    s.icA = v.icA();
    s.fields |= TelemetryField::Temperature | TelemetryField::PhaseCurrents;
}

void fill(TelemetrySample &s, const protocol::MultiTurnAngle &v)
{
    s.multiTurnDeg = v.degrees();
    s.fields |= TelemetryField::MultiTurn;
}

void fill(TelemetrySample &s, const protocol::SingleTurnAngle &v)
{
    s.singleTurnDeg = v.degrees();
    s.fields |= TelemetryField::SingleTurn;
}

void fill(TelemetrySample &s, const protocol::EncoderReading &v)
{
    s.encoder = v.encoder;
    s.fields |= TelemetryField::Encoder;
    s.encoderReading = v;
}

template <typename T> void fill(TelemetrySample &, const T &) {} // no telemetry in it

/// The speed limit of a position command (0xA4, 0xA6, 0xA8), when it carries one.
void setMaxSpeed(TelemetrySample &s, std::optional<quint32> maxSpeedRaw)
{
    if (!maxSpeedRaw)
        return;
    s.commandedMaxSpeedDps = static_cast<double>(*maxSpeedRaw) * protocol::kCentiUnits;
    s.fields |= TelemetryField::CommandedMaxSpeed;
}
} // namespace

std::optional<TelemetrySample> TelemetrySample::fromReply(const protocol::Reply &reply, double time)
{
    TelemetrySample s;
    s.id = reply.id;
    s.time = time;
    s.source = reply.command;
    std::visit([&s](const auto &v) { fill(s, v); }, reply.payload);
    if (!s.fields)
        return std::nullopt;
    return s;
}

std::optional<TelemetrySample> TelemetrySample::fromRequest(const protocol::Request &request,
                                                            std::optional<protocol::Series> series,
                                                            protocol::Generation generation,
                                                            double time)
{
    using protocol::Command;
    TelemetrySample s;
    s.id = request.id;
    s.time = time;
    s.source = request.command;
    if (const auto *v = std::get_if<protocol::SpeedCommand>(&request.payload)) {
        s.commandedSpeedDps = v->speedDps();
        s.fields = TelemetryField::CommandedSpeed;
    } else if (const auto *v = std::get_if<protocol::MultiPositionCommand>(&request.payload)) {
        s.commandedAngleDeg = static_cast<double>(v->angleRaw) * protocol::kCentiUnits;
        s.fields = TelemetryField::CommandedAngle;
        setMaxSpeed(s, v->maxSpeedRaw);
    } else if (const auto *v = std::get_if<protocol::SinglePositionCommand>(&request.payload)) {
        s.commandedSingleTurnDeg = static_cast<double>(v->angleRaw) * protocol::kCentiUnits;
        s.commandedDirection = static_cast<int>(v->direction);
        s.fields = TelemetryField::CommandedSingleTurn | TelemetryField::CommandedDirection;
        setMaxSpeed(s, v->maxSpeedRaw);
    } else if (const auto *v = std::get_if<protocol::IncrementPositionCommand>(&request.payload)) {
        s.commandedIncrementDeg = static_cast<double>(v->angleRaw) * protocol::kCentiUnits;
        s.fields = TelemetryField::CommandedIncrement;
        setMaxSpeed(s, v->maxSpeedRaw);
    } else if (const auto *v = std::get_if<protocol::OpenLoopCommand>(&request.payload)) {
        s.commandedPower = v->power;
        s.fields = TelemetryField::CommandedPower;
    } else if (const auto *v = std::get_if<protocol::TorqueCommand>(&request.payload)) {
        // V2.35 scales iq by series (MF 33/4096, MG/MH 66/4096): unknown series, no value.
        if (generation == protocol::Generation::V2_35 && !series)
            return std::nullopt;
        const protocol::DecodeContext ctx{series.value_or(protocol::Series::MF), generation};
        s.commandedIqA = v->iqRaw * protocol::iqCommandAmpsPerLsb(ctx);
        s.fields = TelemetryField::CommandedIq;
    }
    if (!s.fields)
        return std::nullopt;
    return s;
}

TelemetryFields TelemetrySample::commandedFields()
{
    return TelemetryField::CommandedIq | TelemetryField::CommandedPower |
           TelemetryField::CommandedSpeed | TelemetryField::CommandedAngle |
           TelemetryField::CommandedSingleTurn | TelemetryField::CommandedDirection |
           TelemetryField::CommandedIncrement | TelemetryField::CommandedMaxSpeed;
}

TelemetrySample TelemetrySample::fromState1(int id, const protocol::State1 &state, double time)
{
    TelemetrySample s;
    s.id = id;
    s.time = time;
    s.source = protocol::Command::ReadState1;
    fill(s, state);
    return s;
}

TelemetryFields TelemetrySample::fieldsOf(protocol::Command command,
                                          std::optional<protocol::Series> series, bool v235)
{
    // The decoder's own fill() on an empty payload of that reply: what it fills is what such
    // a reply carries, so this cannot drift from fromReply().
    using protocol::Command;
    TelemetrySample s;
    switch (command) {
    case Command::ReadState1: {
        protocol::State1 v;
        v.generation = v235 ? protocol::Generation::V2_35 : protocol::Generation::V2_3;
        fill(s, v);
        break;
    }
    case Command::ReadState2: {
        protocol::State2 v;
        v.isPower = series == protocol::Series::MS;
        fill(s, v);
        break;
    }
    case Command::ReadState3:
        fill(s, protocol::State3{});
        break;
    case Command::ReadMultiTurn:
        fill(s, protocol::MultiTurnAngle{});
        break;
    case Command::ReadSingleTurn:
        fill(s, protocol::SingleTurnAngle{});
        break;
    case Command::ReadEncoder:
        fill(s, protocol::EncoderReading{});
        break;
    default:
        break;
    }
    return s.fields;
}

void TelemetrySample::merge(const TelemetrySample &newer)
{
    for (const TelemetryFieldInfo &info : TelemetryFieldInfo::all()) {
        if (newer.has(info.field))
            info.copy(*this, newer);
    }
    fields |= newer.fields;
    if (newer.encoderReading)
        encoderReading = newer.encoderReading;
    id = newer.id;
    time = newer.time;
    source = newer.source;
    cycle = newer.cycle;
    cycleTime = newer.cycleTime;
}

} // namespace lk::bus
