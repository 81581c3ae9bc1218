#include "LoopGains.h"

#include <protocol/RequestBuilder.h>

#include <limits>

namespace lk::tuning {

using protocol::Generation;
using protocol::ParamId;

namespace {
const ParamId kLoops[] = {ParamId::AnglePid, ParamId::SpeedPid, ParamId::CurrentPid};

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

QVector<protocol::Request> LoopGains::reads(int id, Generation generation)
{
    QVector<protocol::Request> out;
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
                                           const QVector<protocol::Reply> &replies)
{
    LoopGains g;
    g.generation = generation;
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
