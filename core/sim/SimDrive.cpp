#include "SimDrive.h"

#include <algorithm>
#include <cmath>

namespace lk::sim {

using protocol::Command;
using protocol::Reply;
using protocol::Request;

namespace {
constexpr double kProtectionCheckSeconds = 0.01; // protection reacts within 10 ms
constexpr double kMaxAdvanceSeconds = 60.0;
constexpr double kPi = 3.14159265358979323846;

double positiveMod(double v, double m)
{
    const double r = std::fmod(v, m);
    return r < 0 ? r + m : r;
}

template <typename T> T clampRound(double v, double lo, double hi)
{
    return static_cast<T>(std::lround(std::clamp(v, lo, hi)));
}
} // namespace

SimDrive::SimDrive(int id, const SimDriveModel &model, const std::optional<SimRom> &rom)
    : m_id(id), m_model(model), m_limits(motor::seriesLimits(model.series)),
      m_physics(RotorParams::forSeries(model.series), m_limits.maxCurrentA, m_limits.maxSpeedDps()),
      m_rom(rom.value_or(model.factoryRom(id))), m_protection(m_limits, model.faults)
{
    const motor::ModelNameInfo info = model.nameInfo();
    m_gearRatio = info.gearRatio;
    m_counts = info.countsPerTurn();
    m_protection.setSupplyVoltage(m_limits.nominalSupplyV, m_physics);
    // Spread the drives' initial shaft angles (golden angle) so that a bus does not look
    // cloned; deterministic for tests.
    m_physics.setPositionDeg(positiveMod(id * 137.508, 360.0));
    m_physics.setPlantOptions(model.plant);
    if (m_rom.params.maxSpeedRaw <= 0) // factory setting: the series maximum
        m_rom.params.maxSpeedRaw = static_cast<qint32>(m_limits.maxSpeedDps() * 100.0);
    if (generation() == protocol::Generation::V2_35)
        m_zeroReplyWithOffset = true; // V2.35 answers 0x19 with the new zero (LEN 2)
    restart();
}

void SimDrive::restart()
{
    m_ramPid = m_rom.pid;
    m_ramAccel = m_rom.accelDps2;
    m_ramParams = m_rom.params;
    m_encoderOffset = static_cast<quint16>(m_rom.encoderZero % m_counts);
    m_physics.setGains(m_ramPid);
    m_physics.setAccelerationDps2(m_ramAccel);
    if (generation() == protocol::Generation::V2_35)
        applyParams();
    // A V2.35 drive powers up with the motor on and its brake released, as a real one does;
    // a V2.3 drive waits for its first control command.
    m_runState = isV235() ? RunState::Running : RunState::Off;
    m_brakeReleased = isV235();
    m_command = LoopTarget{};
    m_activeCommand.reset();
    m_protection.restart();
    m_protection.advance(0, m_physics);
    holdShaft();
    checkProtection();
    applyOutput();
    resetAngleReference();
}

void SimDrive::resetAngleReference()
{
    // At power-on the multi-turn angle is the encoder angle: the zero is the last encoder
    // zero crossing below the present position.
    const double offsetDeg = 360.0 * m_encoderOffset / m_counts;
    const double pos = m_physics.positionDeg();
    m_refDeg = pos - positiveMod(pos - offsetDeg, 360.0);
}

void SimDrive::setSupplyVoltage(double volts)
{
    m_protection.setSupplyVoltage(volts, m_physics);
    checkProtection();
}

void SimDrive::setRotorLocked(bool locked)
{
    m_rotorLocked = locked;
    holdShaft();
}

void SimDrive::holdShaft()
{
    // An engaged brake holds the shaft whatever the motor does (V2.35 drives have one).
    m_physics.setRotorLocked(m_rotorLocked || (isV235() && !m_brakeReleased));
}

void SimDrive::advance(double seconds)
{
    if (!(seconds > 0))
        return;
    seconds = std::min(seconds, kMaxAdvanceSeconds);
    while (seconds > 0) {
        const double chunk = std::min(seconds, kProtectionCheckSeconds);
        m_physics.advance(chunk);
        m_protection.advance(chunk, m_physics);
        checkProtection();
        seconds -= chunk;
    }
}

void SimDrive::checkProtection()
{
    // Flags latch until 0x9B; a tripped protection switches the output off, like 0x80 (on
    // V2.35 the motor state then reads off until 0x88).
    if (m_protection.trip(m_physics))
        switchOff();
}

void SimDrive::clearTurnCount()
{
    const double turn = 360.0 * m_gearRatio;
    const double pos = m_physics.positionDeg();
    m_refDeg = pos - positiveMod(pos - m_refDeg, turn);
}

void SimDrive::setMultiTurnAngle(qint64 raw)
{
    m_refDeg = m_physics.positionDeg() - static_cast<double>(raw) * protocol::kCentiUnits;
}

void SimDrive::switchOff()
{
    m_runState = RunState::Off;
    m_command = LoopTarget{};
    m_activeCommand.reset();
    applyOutput();
}

void SimDrive::applyOutput()
{
    const bool on = m_runState == RunState::Running && errorState() == 0;
    m_physics.setTarget(on ? m_command : LoopTarget{});
}

void SimDrive::writeRom()
{
    if (m_romWritten)
        m_romWritten(m_id, series(), m_rom);
}

void SimDrive::applyParams()
{
    // V2.35 keeps gains and the speed ramp in the parameter table (docs/V2.35.md section 6).
    m_ramPid = m_ramParams.physicsGains();
    m_ramAccel = m_ramParams.speedRampDps2;
    m_physics.setGains(m_ramPid);
    m_physics.setDerivativeGains(m_ramParams.derivativeGains());
    m_physics.setAccelerationDps2(m_ramAccel);
}

std::optional<Reply> SimDrive::handle(const Request &r)
{
    // A drive is silent to what its series or its generation does not implement. 0xC0/0xC1
    // reach it only from the CAN front (no RS485 frame decodes to them): a V2.36 drive's.
    const bool canV236 = protocol::CommandTable::info(r.command).canOnly && isV235();
    if (r.id != m_id || !motor::supports(series(), r.command) ||
        (!canV236 && !protocol::CommandTable::availableOn(r.command, generation())))
        return std::nullopt;
    if (canV236)
        return handleV235(r); // nullopt there is silence, not "go on to the motion handler"
    if (auto reply = handleV235(r))
        return reply;
    if (auto reply = handleParameter(r))
        return reply;
    if (auto reply = handleRead(r))
        return reply;
    if (auto reply = handleRunState(r))
        return reply;
    return handleMotion(r);
}

std::optional<Reply> SimDrive::handleParameter(const Request &r)
{
    switch (r.command) {
    case Command::WritePidRam:
    case Command::WritePidRom: {
        const auto gains = std::get<protocol::PidGains>(r.payload);
        m_ramPid = gains;
        m_physics.setGains(gains);
        if (r.command == Command::WritePidRom) {
            m_rom.pid = gains; // 0x32 writes ROM and RAM (ERRATA: the spec's "RAM" is a typo)
            writeRom();
        }
        return Reply{r.command, r.id, gains};
    }
    case Command::WriteAccelRam: {
        const auto accel = std::get<protocol::Acceleration>(r.payload);
        if (m_model.quirks.accelIgnored) // acknowledged, not applied (ERRATA)
            return Reply{r.command, r.id, accel};
        m_ramAccel = accel.dps2; // RAM only: V2.3 has no command that writes accel to ROM
        m_physics.setAccelerationDps2(accel.dps2);
        return Reply{r.command, r.id, accel};
    }
    case Command::WriteEncoderOffset: {
        const auto offset = std::get<protocol::EncoderOffset>(r.payload);
        m_encoderOffset = static_cast<quint16>(offset.offset % m_counts);
        return Reply{r.command, r.id, offset}; // the drive echoes what it received
    }
    case Command::WriteZeroRom: {
        // Effective only after a power cycle (spec): RAM offset and angles stay as they are.
        m_rom.encoderZero = encoderRaw();
        writeRom();
        protocol::ZeroWritten z;
        if (m_zeroReplyWithOffset)
            z.encoderOffset = m_rom.encoderZero;
        return Reply{r.command, r.id, z};
    }
    case Command::ClearAngle:
        if (!m_model.quirks.clearAngleIgnored)
            m_refDeg = m_physics.positionDeg(); // until power-off (ERRATA)
        return Reply{r.command, r.id, protocol::Acknowledged{}};
    case Command::ClearErrors:
        m_protection.clear(m_physics);
        return Reply{r.command, r.id, state1()};
    default:
        return std::nullopt;
    }
}

std::optional<Reply> SimDrive::handleV235(const Request &r)
{
    switch (r.command) {
    case Command::ReadParam: {
        const auto value = m_ramParams.read(std::get<protocol::ParamRead>(r.payload).paramId);
        if (!value)
            return std::nullopt; // an unknown ParamID gets no answer (untested on hardware)
        return Reply{r.command, r.id, *value};
    }
    case Command::WriteParamRam:
    case Command::WriteParamRom: {
        const auto value = std::get<protocol::ParameterValue>(r.payload);
        const bool ok = !m_model.quirks.paramWriteRefused && m_ramParams.write(value);
        if (ok) {
            applyParams();
            if (r.command == Command::WriteParamRom) {
                m_rom.params.write(value); // 0x44 writes flash and RAM
                writeRom();
            }
        }
        return Reply{r.command, r.id,
                     protocol::ParamWriteResult{value.paramId, quint8(ok ? 0 : 1)}};
    }
    case Command::ReadControlParam: {
        const auto value =
            m_ramParams.readControl(std::get<protocol::ControlParamRead>(r.payload).paramId);
        if (!value)
            return std::nullopt; // an unknown ID gets no answer (untested on hardware)
        return Reply{r.command, r.id, *value};
    }
    case Command::WriteControlParam: {
        // RAM only, effective at once; the reply carries the value the drive holds after the
        // write (the old one when the write was refused). No command writes it to ROM.
        const auto value = std::get<protocol::ControlParameter>(r.payload);
        if (!value.id())
            return std::nullopt;
        if (!m_model.quirks.paramWriteRefused && m_ramParams.writeControl(value))
            applyParams();
        return Reply{r.command, r.id, *m_ramParams.readControl(value.paramId)};
    }
    case Command::Brake: {
        const auto action = std::get<protocol::BrakeCommand>(r.payload).action;
        if (action == protocol::BrakeAction::Release)
            m_brakeReleased = true;
        else if (action == protocol::BrakeAction::Engage)
            m_brakeReleased = false;
        holdShaft();
        return Reply{r.command, r.id, protocol::BrakeState{quint8(m_brakeReleased ? 1 : 0)}};
    }
    case Command::ClearTurnCount:
        clearTurnCount();
        return Reply{r.command, r.id, protocol::Acknowledged{}};
    default:
        return std::nullopt;
    }
}

std::optional<Reply> SimDrive::handleRead(const Request &r)
{
    switch (r.command) {
    case Command::ReadPid:
        return Reply{r.command, r.id, m_ramPid};
    case Command::ReadAccel:
        return Reply{r.command, r.id,
                     protocol::Acceleration{m_model.quirks.accelIgnored ? 0 : m_ramAccel}};
    case Command::ReadEncoder:
        return Reply{r.command, r.id, encoderReading()};
    case Command::ReadMultiTurn:
        return Reply{r.command, r.id, protocol::MultiTurnAngle{multiTurnRaw()}};
    case Command::ReadSingleTurn:
        return Reply{r.command, r.id, protocol::SingleTurnAngle{singleTurnRaw()}};
    case Command::ReadState1:
        return Reply{r.command, r.id, state1()};
    case Command::ReadState2:
        return Reply{r.command, r.id, state2()};
    case Command::ReadState3:
        return Reply{r.command, r.id, state3()};
    case Command::ReadModel:
        return Reply{r.command, r.id, modelInfo()};
    default:
        return std::nullopt;
    }
}

std::optional<Reply> SimDrive::handleRunState(const Request &r)
{
    switch (r.command) {
    case Command::MotorOff: // clears the running state and the stored command
        switchOff();
        break;
    case Command::MotorStop: // output off, command kept for 0x88
        if (m_runState == RunState::Running)
            m_runState = RunState::Stopped;
        applyOutput();
        break;
    case Command::MotorRun:
        // V2.3: resumes after 0x81. V2.35: turns a motor that is off back on (with no
        // command: 0x80 cleared it); a stop is left by a new control command instead.
        if (errorState() == 0 && (!isV235() || m_runState == RunState::Off))
            m_runState = RunState::Running;
        applyOutput();
        break;
    default:
        return std::nullopt;
    }
    return Reply{r.command, r.id, protocol::Acknowledged{}};
}

Reply SimDrive::handleMotion(const Request &r)
{
    // A drive in protection answers with its state but does not move until 0x9B clears it; a
    // V2.35 drive that is off answers too, and stays off until 0x88 (docs/V2.35.md section 11).
    if (errorState() == 0 && !(isV235() && m_runState == RunState::Off)) {
        if (const auto target = motionTarget(r)) {
            m_command = *target;
            m_activeCommand = r.command;
            m_runState = RunState::Running;
            applyOutput();
        }
    }
    return Reply{r.command, r.id, state2()};
}

double SimDrive::maxSpeedFor(const std::optional<quint32> &maxSpeedRaw) const
{
    double driveMax = m_limits.maxSpeedDps();
    if (generation() == protocol::Generation::V2_35) // bounded by the stored Max Speed too
        driveMax = std::min(driveMax, m_ramParams.maxSpeedRaw * protocol::kCentiUnits);
    // A max speed of 0 still moves: the drive then uses its stored maximum (docs/V2.35.md s.12).
    if (!maxSpeedRaw || *maxSpeedRaw == 0)
        return driveMax;
    return std::min(driveMax, *maxSpeedRaw * protocol::kCentiUnits);
}

double SimDrive::singleTurnTargetDeg(const protocol::SinglePositionCommand &c) const
{
    // The single-turn angle of a geared drive spans one output turn (0..36000 x ratio - 1,
    // as 0x94 reports it: ERRATA, docs/V2.35.md, docs/CAN.md); its target lies in that turn.
    const double turn = 360.0 * m_gearRatio;
    const double pos = m_physics.positionDeg();
    const double current = positiveMod(pos - m_refDeg, turn);
    const double target = positiveMod(c.angleRaw * protocol::kCentiUnits, turn);
    const double delta = c.direction == protocol::SpinDirection::Clockwise
                             ? positiveMod(target - current, turn)
                             : -positiveMod(current - target, turn);
    return pos + delta;
}

std::optional<LoopTarget> SimDrive::motionTarget(const Request &r) const
{
    LoopTarget t;
    t.maxSpeedDps = m_limits.maxSpeedDps();
    if (const auto *c = std::get_if<protocol::OpenLoopCommand>(&r.payload)) {
        t.mode = LoopMode::OpenLoop;
        t.voltageFraction = c->power / 1000.0; // not limited by the drive (ERRATA)
    } else if (const auto *c = std::get_if<protocol::TorqueCommand>(&r.payload)) {
        t.mode = LoopMode::Torque;
        // Not limited by the drive (ERRATA); V2.35 MF drives use 33/4096 A per LSB.
        t.currentA = c->iqRaw * protocol::iqCommandAmpsPerLsb(context());
    } else if (const auto *c = std::get_if<protocol::SpeedCommand>(&r.payload)) {
        t.mode = LoopMode::Speed;
        t.speedDps = c->speedDps();
        // CAN V2.36's 0xA2 carries the torque limit of this command. What a limit of 0 does
        // is unknown (docs/CAN.md): modelled as none of its own, the drive's limit stays.
        if (c->iqLimitRaw && *c->iqLimitRaw != 0)
            t.currentLimitA = std::abs(*c->iqLimitRaw) * protocol::iqCommandAmpsPerLsb(context());
    } else if (const auto *c = std::get_if<protocol::MultiPositionCommand>(&r.payload)) {
        t.mode = LoopMode::Position;
        t.positionDeg = m_refDeg + static_cast<double>(c->angleRaw) * protocol::kCentiUnits;
        t.maxSpeedDps = maxSpeedFor(c->maxSpeedRaw);
    } else if (const auto *c = std::get_if<protocol::SinglePositionCommand>(&r.payload)) {
        t.mode = LoopMode::Position;
        t.positionDeg = singleTurnTargetDeg(*c);
        t.maxSpeedDps = maxSpeedFor(c->maxSpeedRaw);
    } else if (const auto *c = std::get_if<protocol::IncrementPositionCommand>(&r.payload)) {
        // Increments add to a running position target, so that quick jog steps do not lose
        // distance; otherwise they start from where the shaft is.
        const bool chained =
            m_runState == RunState::Running && m_command.mode == LoopMode::Position;
        const double base = chained ? m_command.positionDeg : m_physics.positionDeg();
        t.mode = LoopMode::Position;
        t.positionDeg = base + c->angleRaw * protocol::kCentiUnits;
        t.maxSpeedDps = maxSpeedFor(c->maxSpeedRaw);
    } else {
        return std::nullopt;
    }
    return t;
}

quint16 SimDrive::encoderRaw() const
{
    const double turn = positiveMod(m_physics.positionDeg(), 360.0) / 360.0;
    const auto counts = static_cast<qint64>(std::floor(turn * m_counts));
    return static_cast<quint16>(std::clamp<qint64>(counts, 0, m_counts - 1));
}

quint16 SimDrive::encoder() const
{
    return static_cast<quint16>((encoderRaw() - m_encoderOffset + m_counts) % m_counts);
}

qint64 SimDrive::multiTurnRaw() const
{
    return std::llround((m_physics.positionDeg() - m_refDeg) / protocol::kCentiUnits);
}

quint32 SimDrive::singleTurnRaw() const
{
    const qint64 range = std::max<qint64>(1, std::llround(36000.0 * m_gearRatio));
    const qint64 v = multiTurnRaw() % range;
    return static_cast<quint32>(v < 0 ? v + range : v);
}

qint16 SimDrive::iqRaw() const
{
    return clampRound<qint16>(iqA() / protocol::iqReplyAmpsPerLsb(context()), -2048, 2048);
}

qint16 SimDrive::powerRaw() const
{
    const double supply = m_physics.supplyVoltage();
    if (supply <= 0)
        return 0;
    return clampRound<qint16>(m_physics.voltage() / supply * 1000.0, -1000, 1000);
}

protocol::State1 SimDrive::state1() const
{
    protocol::State1 s;
    s.generation = generation();
    s.temperatureC = clampRound<qint8>(temperatureC(), -128, 127);
    s.errorState = errorState();
    if (generation() == protocol::Generation::V2_3) {
        s.voltageRaw = clampRound<quint16>(busVoltage() * 10.0, 0, 65535);
        return s;
    }
    s.voltageRaw = static_cast<quint16>(clampRound<qint16>(busVoltage() * 100.0, 0, 32767));
    // Bus current: the power the winding draws from the supply.
    const double supply = std::max(busVoltage(), 1e-3);
    const double busA = std::fabs(m_physics.voltage() * iqA()) / supply;
    s.busCurrentRaw = clampRound<qint16>(busA * 100.0, -32768, 32767);
    s.motorStateRaw = m_runState == RunState::Off ? 0x10 : 0x00;
    return s;
}

protocol::State2 SimDrive::state2() const
{
    protocol::State2 s;
    s.temperatureC = clampRound<qint8>(temperatureC(), -128, 127);
    s.isPower = m_limits.repliesCarryPower;
    s.torqueRaw = s.isPower ? powerRaw() : iqRaw();
    s.speedDps = clampRound<qint16>(speedDps(), -32768, 32767);
    s.encoder = encoder();
    return s;
}

protocol::State3 SimDrive::state3() const
{
    // Phase currents of a sinusoidal FOC drive with id = 0.
    const double theta = m_physics.electricalAngleRad();
    const double iq = iqA();
    const double lsb = protocol::phaseAmpsPerLsb(context());
    auto raw = [lsb](double amps) { return clampRound<qint16>(amps / lsb, -32768, 32767); };
    protocol::State3 s;
    s.temperatureC = clampRound<qint8>(temperatureC(), -128, 127);
    s.iaRaw = raw(-iq * std::sin(theta));
    s.ibRaw = raw(-iq * std::sin(theta - 2.0 * kPi / 3.0));
    s.icRaw = raw(-iq * std::sin(theta + 2.0 * kPi / 3.0));
    return s;
}

protocol::EncoderReading SimDrive::encoderReading() const
{
    return protocol::EncoderReading{encoder(), encoderRaw(), m_encoderOffset};
}

protocol::ModelInfo SimDrive::modelInfo() const
{
    protocol::ModelInfo m;
    m.driverName = m_model.driverName;
    m.motorName = m_model.motorName;
    m.hardwareRaw = m_model.hardwareRaw;
    m.firmwareRaw = m_model.firmwareRaw;
    m.generation = generation();
    if (generation() == protocol::Generation::V2_35) {
        m.motorVersionRaw = m_model.motorVersionRaw;
        // A unique ID that stays the same for the same bus position.
        m.motorId = QByteArray::fromHex("35373530303273187803") + QByteArray(1, char(0x40 + m_id)) +
                    QByteArray(1, char(0x4B));
    }
    return m;
}

} // namespace lk::sim
