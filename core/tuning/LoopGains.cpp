#include "LoopGains.h"

#include <protocol/RequestBuilder.h>

#include <limits>

namespace lk::tuning {

using protocol::Generation;
using protocol::ParamId;

namespace {
const ParamId kLoops[] = {ParamId::AnglePid, ParamId::SpeedPid, ParamId::CurrentPid};

using protocol::ControlParamId;
/// What LoopGains holds on CAN V2.36: the three PIDs and the input speed ramp (0x26).
const ControlParamId kControlReads[] = {ControlParamId::AnglePid, ControlParamId::SpeedPid,
                                        ControlParamId::CurrentPid, ControlParamId::InputSpeedRamp};

bool isCan236(Generation generation, protocol::Link link)
{
    return link == protocol::Link::Can && generation == Generation::V2_35;
}

/// The loop a CAN V2.36 PID parameter holds; nullptr for the speed ramp.
PidTriple *loopOf(LoopGains &g, ControlParamId id)
{
    switch (id) {
    case ControlParamId::AnglePid:
        return &g.angle;
    case ControlParamId::SpeedPid:
        return &g.speed;
    case ControlParamId::CurrentPid:
        return &g.current;
    default:
        return nullptr;
    }
}

std::optional<LoopGains> decodeCan236(LoopGains g, const QVector<protocol::Reply> &replies)
{
    int found = 0;
    for (const protocol::Reply &r : replies) {
        const auto *v = std::get_if<protocol::ControlParameter>(&r.payload);
        if (!v || !v->id())
            continue;
        if (PidTriple *loop = loopOf(g, *v->id())) {
            *loop = {v->pid()[0], v->pid()[1], v->pid()[2]};
            ++found;
        } else if (*v->id() == ControlParamId::InputSpeedRamp) {
            g.accelerationDps2 = v->value();
            ++found;
        }
    }
    return found == 4 ? std::optional<LoopGains>(g) : std::nullopt;
}

PidTriple *loopOf(LoopGains &g, ParamId id)
{
    switch (id) {
    case ParamId::AnglePid:
        return &g.angle;
    case ParamId::SpeedPid:
        return &g.speed;
    case ParamId::CurrentPid:
        return &g.current;
    default:
        return nullptr;
    }
}
} // namespace

QVector<protocol::Request> LoopGains::reads(int id, Generation generation, protocol::Link link)
{
    QVector<protocol::Request> out;
    if (isCan236(generation, link)) {
        for (ControlParamId p : kControlReads)
            if (const auto b = protocol::build::readControlParam(id, p); b.ok())
                out.append(*b.request);
        return out;
    }
    if (generation == Generation::V2_3) {
        for (protocol::Command c : {protocol::Command::ReadPid, protocol::Command::ReadAccel})
            if (const auto b = protocol::build::plain(c, id); b.ok())
                out.append(*b.request);
        return out;
    }
    for (ParamId p :
         {ParamId::AnglePid, ParamId::SpeedPid, ParamId::CurrentPid, ParamId::SpeedRamp})
        if (const auto b = protocol::build::readParam(id, p); b.ok())
            out.append(*b.request);
    return out;
}

std::optional<LoopGains> LoopGains::decode(Generation generation,
                                           const QVector<protocol::Reply> &replies,
                                           protocol::Link link)
{
    LoopGains g;
    g.generation = generation;
    g.link = link;
    if (isCan236(generation, link))
        return decodeCan236(g, replies);
    int found = 0;
    if (generation == Generation::V2_3) {
        for (const protocol::Reply &r : replies) {
            if (const auto *p = std::get_if<protocol::PidGains>(&r.payload)) {
                g.angle = {p->angleKp, p->angleKi, 0};
                g.speed = {p->speedKp, p->speedKi, 0};
                g.current = {p->iqKp, p->iqKi, 0};
                ++found;
            } else if (const auto *a = std::get_if<protocol::Acceleration>(&r.payload)) {
                g.accelerationDps2 = a->dps2;
                ++found;
            }
        }
        return found == 2 ? std::optional<LoopGains>(g) : std::nullopt;
    }
    for (const protocol::Reply &r : replies) {
        const auto *v = std::get_if<protocol::ParameterValue>(&r.payload);
        if (!v || !v->id())
            continue;
        if (PidTriple *loop = loopOf(g, *v->id())) {
            *loop = {v->pidKp(), v->pidKi(), v->pidKd()};
            ++found;
        } else if (*v->id() == ParamId::SpeedRamp) {
            g.accelerationDps2 = v->asInt32();
            ++found;
        }
    }
    return found == 4 ? std::optional<LoopGains>(g) : std::nullopt;
}

QVector<protocol::Request> LoopGains::ramWrites(int id) const
{
    QVector<protocol::Request> out;
    if (isCan236(generation, link)) { // 0xC1: RAM is all there is
        LoopGains copy = *this;
        for (ControlParamId p : kControlReads) {
            const PidTriple *t = loopOf(copy, p);
            const auto b = t ? protocol::build::writeControlParamPid(id, p, t->kp, t->ki, t->kd)
                             : protocol::build::writeControlParam(id, p, double(accelerationDps2));
            if (b.ok())
                out.append(*b.request);
        }
        return out;
    }
    if (generation == Generation::V2_3) {
        const auto b = protocol::build::writePid(id, angle.kp, angle.ki, speed.kp, speed.ki,
                                                 current.kp, current.ki, false);
        if (b.ok())
            out.append(*b.request);
        if (const auto a = protocol::build::writeAcceleration(id, accelerationDps2); a.ok())
            out.append(*a.request);
        return out;
    }
    for (ParamId p : kLoops) {
        const PidTriple &t = *loopOf(const_cast<LoopGains &>(*this), p);
        if (const auto b = protocol::build::writeParamPid(id, p, t.kp, t.ki, t.kd, false); b.ok())
            out.append(*b.request);
    }
    const auto ramp =
        protocol::build::writeParam(id, ParamId::SpeedRamp, double(accelerationDps2), false);
    if (ramp.ok())
        out.append(*ramp.request);
    return out;
}

quint16 LoopGains::maxGain() const
{
    return generation == Generation::V2_3 ? std::numeric_limits<quint8>::max()
                                          : std::numeric_limits<quint16>::max();
}

} // namespace lk::tuning
