#pragma once

// One simulated drive on a SimBus, on the test's clock: each request goes out as bytes, the
// drive's physics run to the moment its last byte is on the wire, and the reply comes back
// after the drive's delay and its own wire time at the rig's baud. A step test runs as
// StepTestRunner runs it on a focused poll plan: each setpoint at its time, read_state2 in
// every gap, each reply a sample at its arrival (plus a host's timestamp jitter). Time stands
// still between transactions, so a loaded machine changes nothing; the figures are those of
// a bus that is never idle at `baud`.
#include <bus/TelemetrySample.h>
#include <protocol/Reply.h>
#include <protocol/RequestBuilder.h>
#include <protocol/StreamParser.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <tuning/GainSearchStrategy.h>
#include <tuning/LoopGains.h>
#include <tuning/StepRun.h>
#include <tuning/StepTestPlan.h>

#include <memory>
#include <optional>

namespace lk::test {

class SimStepRig {
public:
    /// Drive `id` of `spec` ("1:MF@2.35"); `hostGapS`: the host's time between a reply and its
    /// next request; `jitterS`: the largest delay of a sample's timestamp after its arrival.
    SimStepRig(const QString &spec, int baud = 1000000, double hostGapS = 0.0003,
               double jitterS = 0.0003)
        : m_bus(sim::SimBus::fromSpec(*sim::SimBusSpec::parse(spec))), m_baud(baud),
          m_hostGapS(hostGapS), m_jitterS(jitterS)
    {
        m_id = m_bus->ids().first();
        const sim::SimDrive *drive = m_bus->drive(m_id);
        m_context.series = drive->model().series;
        m_context.generation = drive->model().generation;
    }

    int id() const { return m_id; }
    protocol::Series series() const { return m_context.series; }
    protocol::Generation generation() const { return m_context.generation; }
    double now() const { return m_now; }
    sim::SimBus &bus() { return *m_bus; }

    /// One request and its reply (nullopt: none came), the clock moved past both.
    std::optional<protocol::Reply> transact(const protocol::Request &request)
    {
        const QByteArray bytes = request.encode();
        const double received = m_now + sim::SimBus::wireSeconds(bytes.size(), m_baud);
        const QList<sim::SimReply> replies = m_bus->receive(bytes, received);
        m_now = received + m_hostGapS;
        if (replies.isEmpty())
            return std::nullopt;
        const sim::SimReply &r = replies.first();
        m_now = received + r.delaySeconds + sim::SimBus::wireSeconds(r.bytes.size(), m_baud);
        m_lastArrival = m_now;
        m_now += m_hostGapS;
        std::optional<protocol::Reply> out;
        protocol::StreamParser parser;
        parser.feed(r.bytes.constData(), r.bytes.size(), [&](const protocol::ParseEvent &e) {
            if (e.isFrame && !out)
                out = protocol::decodeReply(e.frame, m_context).reply;
        });
        return out;
    }

    std::optional<tuning::LoopGains> readGains()
    {
        QVector<protocol::Reply> replies;
        for (const protocol::Request &r : tuning::LoopGains::reads(m_id, m_context.generation))
            if (const auto reply = transact(r))
                replies.append(*reply);
        return tuning::LoopGains::decode(m_context.generation, replies);
    }

    bool writeGains(const tuning::LoopGains &gains)
    {
        bool ok = true;
        for (const protocol::Request &r : gains.ramWrites(m_id))
            ok = transact(r).has_value() && ok;
        return ok;
    }

    /// The multi-turn angle (0x92), deg; nullopt: no answer.
    std::optional<double> readAngle()
    {
        const auto reply =
            transact(*protocol::build::plain(protocol::Command::ReadMultiTurn, m_id).request);
        const auto *a = reply ? std::get_if<protocol::MultiTurnAngle>(&reply->payload) : nullptr;
        return a ? std::optional<double>(a->degrees()) : std::nullopt;
    }

    /// A step test as StepTestRunner runs it: the trace from the first setpoint's reply on,
    /// edges at their replies' times. Speed: read_state2 in every gap, each reply a sample.
    /// Position: the angle read first (the plan's targets start there), then rounds of
    /// read_state2 and read_multi_turn in the gaps, each angle a sample with the round's
    /// current as its effort. An empty trace: refused.
    tuning::StepTrace runStep(const tuning::StepTestSpec &spec, const safety::SoftLimits &limits)
    {
        const bool position = spec.loop == tuning::StepLoop::Position;
        safety::DrivePosition at;
        if (position)
            at.angleDeg = readAngle();
        const tuning::StepTestPlan plan =
            tuning::StepTestPlan::make(spec, m_context.series, limits, at);
        tuning::StepTrace trace;
        trace.loop = spec.loop;
        if (!plan.allowed())
            return trace;
        const double start = m_now;
        int next = 0;
        bool first = true;
        bool readAngleNext = false;
        double roundEffort = tuning::StepTrace::missing();
        while (m_now - start < plan.endS() || next < plan.setpoints().size()) {
            const bool due = next < plan.setpoints().size() &&
                             plan.setpoints().at(next).atS <= m_now - start + 0.0005;
            const tuning::StepSetpoint *setpoint = due ? &plan.setpoints().at(next++) : nullptr;
            const protocol::Command poll = position && readAngleNext
                                               ? protocol::Command::ReadMultiTurn
                                               : protocol::Command::ReadState2;
            if (!setpoint && position)
                readAngleNext = !readAngleNext;
            const std::optional<protocol::Reply> reply = transact(
                setpoint ? setpoint->request : *protocol::build::plain(poll, m_id).request);
            if (!reply) {
                first = first && !setpoint;
                continue;
            }
            const double time = m_lastArrival + jitter();
            if (setpoint && setpoint->role == tuning::StepSetpoint::Role::Edge)
                trace.edges.append(tuning::StepEdge{time, setpoint->previous, setpoint->target});
            first = first && !setpoint;
            if (first)
                continue; // before the first setpoint's reply: not the trace's
            const std::optional<bus::TelemetrySample> s =
                bus::TelemetrySample::fromReply(*reply, time);
            if (!s)
                continue;
            const double effort = s->has(bus::TelemetryField::IqA) ? s->iqA
                                  : s->has(bus::TelemetryField::Power)
                                      ? s->power
                                      : tuning::StepTrace::missing();
            trace.effortIsPower = trace.effortIsPower || s->has(bus::TelemetryField::Power);
            if (position) {
                if (!setpoint && poll == protocol::Command::ReadState2)
                    roundEffort = effort;
                if (s->has(bus::TelemetryField::MultiTurn))
                    trace.append(time, s->multiTurnDeg, roundEffort);
                continue;
            }
            if (s->has(bus::TelemetryField::Speed))
                trace.append(time, s->speedDps, effort);
        }
        return trace;
    }

private:
    double jitter()
    {
        // A fixed sequence (an LCG): the same run every time.
        m_lcg = m_lcg * 1664525u + 1013904223u;
        return m_jitterS * double(m_lcg >> 8) / double(1u << 24);
    }

    std::unique_ptr<sim::SimBus> m_bus;
    protocol::DecodeContext m_context;
    int m_id = 1;
    int m_baud;
    double m_hostGapS;
    double m_jitterS;
    double m_now = 0;
    double m_lastArrival = 0;
    quint32 m_lcg = 12345;
};

} // namespace lk::test
