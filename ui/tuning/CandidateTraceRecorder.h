#pragma once

#include <bus/RequestResult.h>
#include <bus/TelemetrySample.h>
#include <tuning/StepTrace.h>

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QVector>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

/// The speed trace of each candidate a gain search steps, recorded beside the search from the
/// session's signals (tuning::GainSearchRunner keeps only each candidate's figures): every
/// sample of the drive's speed (the step test's polls and the setpoints' replies), and the
/// acknowledged speed setpoints paired in order with their replies' samples, as the step test
/// pairs them. cut() closes one candidate's trace at its score; a setpoint that differs from
/// the one before is an edge, at its reply's time.
class CandidateTraceRecorder : public QObject {
    Q_OBJECT
public:
    explicit CandidateTraceRecorder(QObject *parent = nullptr);

    /// Forgets every trace and records drive `id` on `session` from now on.
    void start(bus::BusSession *session, int id);
    void stop();
    /// Ends the current candidate's trace (from the previous cut on) and keeps it.
    void cut();
    /// The traces cut, one per candidate in order.
    const QVector<tuning::StepTrace> &traces() const { return m_traces; }

private:
    void onCompleted(const bus::RequestResult &result);
    void onTelemetry(const bus::TelemetryBatch &batch);

    QPointer<bus::BusSession> m_session;
    int m_id = 0;
    struct Sample {
        bus::TelemetrySample sample;
        int setpoint = -1; ///< a setpoint's reply: its index into m_setpoints
    };
    QVector<double> m_setpoints; ///< acknowledged speed setpoints, dps, in order
    QVector<Sample> m_samples;   ///< the drive's speed samples, in order
    int m_replies = 0;           ///< setpoint replies among them
    int m_cutAt = 0;             ///< samples before this belong to earlier traces
    QVector<tuning::StepTrace> m_traces;
    QMetaObject::Connection m_completed;
    QMetaObject::Connection m_telemetry;
};

} // namespace lk::ui
