#include "SetpointGenerator.h"

#include "DriveText.h"

#include <bus/BusSession.h>

namespace lk::ui {

SetpointGenerator::SetpointGenerator(QObject *parent) : QObject(parent) {}

SetpointGenerator::~SetpointGenerator()
{
    if (isRunning() && m_session)
        m_session->stopSetpointStream();
}

void SetpointGenerator::setSession(bus::BusSession *session)
{
    if (session == m_session)
        return;
    if (isRunning() && m_session)
        m_session->stopSetpointStream();
    m_stream = 0;
    disconnect(m_stoppedConnection);
    disconnect(m_failedConnection);
    m_session = session;
    if (!session)
        return;
    m_stoppedConnection = connect(session, &bus::BusSession::setpointStreamStopped, this,
                                  &SetpointGenerator::onStopped);
    m_failedConnection =
        connect(session, &bus::BusSession::setpointFailed, this, &SetpointGenerator::onFailed);
}

void SetpointGenerator::start(const bus::SetpointStreamPlan &plan)
{
    if (!m_session)
        return;
    m_plan = plan;
    m_stream = m_session->startSetpointStream(plan);
    m_plan.stream = m_stream;
    emit started();
}

void SetpointGenerator::stop(const QString &reason)
{
    if (!isRunning())
        return;
    m_stream = 0;
    if (m_session)
        m_session->stopSetpointStream();
    emit stopped(reason);
}

void SetpointGenerator::onStopped(const bus::SetpointStop &stop)
{
    // A stream stopped here already, or replaced since, has nothing more to say.
    if (stop.stream != m_stream || m_stream == 0)
        return;
    m_stream = 0;
    const QString text = DriveText::setpointStop(stop, m_plan.series);
    if (stop.reason == bus::SetpointStopReason::Refused) {
        MotionOutcome out;
        out.refusal = text;
        out.limit = stop.verdict.kind;
        out.fieldError = stop.fieldError;
        emit refused(out);
    }
    emit stopped(text);
}

void SetpointGenerator::onFailed(quint64 stream, const bus::RequestResult &result)
{
    if (isRunning() && stream == m_stream)
        emit setpointFailed(result);
}

} // namespace lk::ui
