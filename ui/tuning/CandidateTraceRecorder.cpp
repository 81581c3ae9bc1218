#include "CandidateTraceRecorder.h"

#include <bus/BusSession.h>

namespace lk::ui {

using bus::TelemetryField;
using tuning::StepTrace;

CandidateTraceRecorder::CandidateTraceRecorder(QObject *parent) : QObject(parent) {}

void CandidateTraceRecorder::start(bus::BusSession *session, int id)
{
    stop();
    m_session = session;
    m_id = id;
    m_setpoints.clear();
    m_samples.clear();
    m_traces.clear();
    m_replies = 0;
    m_cutAt = 0;
    if (!session)
        return;
    m_completed = connect(session, &bus::BusSession::requestCompleted, this,
                          &CandidateTraceRecorder::onCompleted);
    m_telemetry = connect(session, &bus::BusSession::telemetryReceived, this,
                          &CandidateTraceRecorder::onTelemetry);
}

void CandidateTraceRecorder::stop()
{
    disconnect(m_completed);
    disconnect(m_telemetry);
}

void CandidateTraceRecorder::onCompleted(const bus::RequestResult &result)
{
    const auto *speed = std::get_if<protocol::SpeedCommand>(&result.request.payload);
    if (result.request.id == m_id && speed && result.ok())
        m_setpoints.append(speed->speedDps());
}

void CandidateTraceRecorder::onTelemetry(const bus::TelemetryBatch &batch)
{
    for (const bus::TelemetrySample &s : batch) {
        if (s.id != m_id || !s.has(TelemetryField::Speed))
            continue;
        // The replies to the setpoints come in the order they were sent.
        m_samples.append({s, s.source == protocol::Command::Speed ? m_replies++ : -1});
    }
}

void CandidateTraceRecorder::cut()
{
    StepTrace trace;
    trace.loop = tuning::StepLoop::Speed;
    const int n = int(m_samples.size());
    for (int k = m_cutAt; k < n; ++k) {
        const bus::TelemetrySample &s = m_samples.at(k).sample;
        const double effort = s.has(TelemetryField::IqA)     ? s.iqA
                              : s.has(TelemetryField::Power) ? double(s.power)
                                                             : StepTrace::missing();
        trace.effortIsPower = trace.effortIsPower || s.has(TelemetryField::Power);
        trace.append(s.time, s.speedDps, effort);
        const int i = m_samples.at(k).setpoint;
        if (i >= 1 && i < m_setpoints.size() && m_setpoints.at(i) != m_setpoints.at(i - 1))
            trace.edges.append({s.time, m_setpoints.at(i - 1), m_setpoints.at(i)});
    }
    m_cutAt = n;
    m_traces.append(trace);
}

} // namespace lk::ui
