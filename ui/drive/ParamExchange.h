#pragma once

#include "ParamSetSpec.h"

#include <bus/RequestResult.h>

#include <QtCore/QObject>
#include <QtCore/QStringList>

#include <optional>

namespace lk::ui {

class RequestTracker;

/// Runs the read / write / read-back cycle of one ParamSetSpec on one drive through a view's
/// RequestTracker: a read sends every request of the set and completes when all have answered
/// (or failed); a write sends each frame once (ROM: never retried), checks the success flag of
/// V2.35 replies, and reads back. Knows nothing of widgets.
class ParamExchange : public QObject {
    Q_OBJECT
public:
    ParamExchange(RequestTracker *tracker, QObject *parent = nullptr);

    /// The set to read and write (not owned); forgets what was read.
    void setSpec(const ParamSetSpec *spec);
    const ParamSetSpec *spec() const { return m_spec; }
    /// Forgets what was read and what a write expected (another drive or connection).
    void clear();
    /// The tracker forgot its requests: none is outstanding any more.
    void forgetOutstanding();

    /// Reads the whole set from drive `id`; readFinished follows.
    void read(int id);
    /// Sends the frames that write `values` (ROM: each once, never retried), then reads back.
    /// Nothing is sent and an error text is returned when a frame cannot be built.
    QString write(int id, const ParamValues &values, bool rom);

    bool busy() const { return m_outstanding > 0; }
    const HeldValues &held() const { return m_held; }
    /// Every value of the set was read by the last read.
    bool complete() const { return ParamSetSpec::known(m_held).has_value(); }
    /// Why the last read did not complete.
    QString readFailure() const { return m_readFailure; }
    /// What the last write sent, until takeSent(); the read-back is compared with it.
    std::optional<SentValues> takeSent();
    /// Why frames of the last write failed (not answered, or refused with flag 1); empty when
    /// every frame was acknowledged.
    QStringList writeFailures() const { return m_writeFailures; }

signals:
    /// A read (or a write's read-back) of drive `id` finished.
    void readFinished(int id);
    /// A ROM write frame of drive `id` was acknowledged (flag 0): `fields` of `values` are in
    /// its flash now.
    void romWritten(int id, const lk::ui::ParamValues &values, const QVector<int> &fields);
    /// A RAM write frame of drive `id` was acknowledged.
    void ramWritten(int id);

private:
    void onWriteResult(int id, const ParamWrite &frame, const ParamValues &values,
                       const bus::RequestResult &r);
    QString fieldNames(const QVector<int> &fields) const;

    RequestTracker *m_tracker;
    const ParamSetSpec *m_spec = nullptr;
    HeldValues m_held;
    QVector<protocol::Reply> m_replies;
    QString m_readFailure;
    std::optional<SentValues> m_sent;
    QStringList m_writeFailures;
    int m_outstanding = 0;
};

} // namespace lk::ui
