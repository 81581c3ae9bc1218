#pragma once

#include "BusRequest.h"
#include "PollPlan.h"
#include "PollScheduler.h"
#include "SingleShotTimer.h"

#include <QtCore/QObject>

#include <functional>
#include <memory>
#include <optional>

namespace lk::bus {

/// Runs the poll plan in the bus's idle time, on the bus thread: hands out PollScheduler's next
/// due read as a Background request (never retried: a missed sample is read again the next
/// round), and when none is due arms a timer for the next one. It holds while suspended (the
/// link is down); its owner resumes it. The owner sends then: `due` runs when the timer fires,
/// `ended` when a poll has ended. The speed watch's reads (setWatched) go out with or without
/// a plan and are never held: whether anything is sent is the link's to decide.
class PollRunner : public QObject {
    Q_OBJECT
public:
    PollRunner(const SingleShotTimerFactory &timers, std::function<void()> due,
               std::function<void()> ended, QObject *parent = nullptr);
    ~PollRunner() override;

    PollScheduler &scheduler() { return m_poller; }
    bool isActive() const { return m_poller.isActive(); }
    bool isSuspended() const { return m_suspended; }

    /// Polls `plan` from `now`; suspended from the start when the link is not open.
    void start(const PollPlan &plan, double now, bool linkOpen);
    void stop();
    /// Forgets the plan without a word (the bus is shut down).
    void clear();
    /// Holds or resumes a running plan (a plan that is not running is left alone).
    void setSuspended(bool suspended);
    /// The drives the speed watch reads often (PollScheduler::setWatched).
    void setWatched(const QVector<int> &ids) { m_poller.setWatched(ids); }
    /// The poll due at `now`, or nullopt (none due: the timer is armed for the next one).
    std::optional<PendingRequest> next(double now);

signals:
    /// Polling started, stopped, was suspended or resumed.
    void pollingChanged(bool active);

private:
    void noteAnswer(const RequestResult &res);

    PollScheduler m_poller;
    std::function<void()> m_ended;
    bool m_suspended = false;
    std::unique_ptr<SingleShotTimer> m_timer;
};

} // namespace lk::bus
