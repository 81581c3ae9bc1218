#pragma once

#include "ManualClock.h"

#include <bus/BusTimeSource.h>
#include <bus/SingleShotTimer.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QEvent>
#include <QtCore/QObject>
#include <QtCore/QVector>

#include <functional>
#include <limits>
#include <memory>

namespace lk::testsupport {

/// Timers a test fires by hand: a SingleShotTimerFactory whose timers record when they were
/// started and for how long, and time out only when the test says so. Given a ManualClock,
/// they also know when they are due, and advance() runs the clock forward firing each due
/// timer in due order (started first on a tie), with the thread's posted events (queued
/// signals, queued replies) delivered between firings, as an event loop would.
class ManualTimers {
public:
    /// One timer as the object under test sees it, and the handle the test keeps.
    struct State {
        std::function<void()> onTimeout;
        bool active = false;
        int lastMs = -1; ///< the interval of the last start(); -1: never started
        int starts = 0;
        Qt::TimerType type = Qt::CoarseTimer;
        qint64 dueNs = 0;     ///< clock time of the timeout (with a clock)
        quint64 order = 0;    ///< start sequence: ties fire in start order
        bool oneShot = false; ///< made by singleShot(): forgotten once it has fired
    };

    ManualTimers() = default;
    explicit ManualTimers(std::shared_ptr<ManualClock> clock) : m_clock(std::move(clock)) {}

    bus::SingleShotTimerFactory factory()
    {
        return [this](QObject *, std::function<void()> onTimeout, Qt::TimerType type) {
            auto state = std::make_shared<State>();
            state->onTimeout = std::move(onTimeout);
            state->type = type;
            m_timers.append(state);
            return std::unique_ptr<bus::SingleShotTimer>(new Timer(state, this));
        };
    }
    /// The clock and these timers, for a BusWorker (needs the clock constructor).
    bus::BusTimeSource timeSource() { return bus::BusTimeSource{m_clock, factory()}; }
    const std::shared_ptr<ManualClock> &clock() const { return m_clock; }

    int count() const { return int(m_timers.size()); }
    const State &at(int i) const { return *m_timers.at(i); }
    /// Time out timer `i` if it is running (as its interval passing would); false if it was
    /// not.
    bool fire(int i = 0)
    {
        const std::shared_ptr<State> s = m_timers.at(i); // alive while its callback runs
        if (!s->active)
            return false;
        s->active = false;
        s->onTimeout();
        return true;
    }

    /// Run `f` once, `ms` from now on the clock (a QTimer::singleShot that advance() fires).
    void singleShot(int ms, std::function<void()> f)
    {
        // Fired ones go: a test that schedules every reply must not slow down as it runs.
        m_timers.removeIf([](const std::shared_ptr<State> &t) { return t->oneShot && !t->active; });
        m_oneShots.removeIf([](const std::shared_ptr<Timer> &t) { return !t->isActive(); });
        auto state = std::make_shared<State>();
        state->onTimeout = std::move(f);
        state->oneShot = true;
        m_timers.append(state);
        m_oneShots.append(std::make_shared<Timer>(state, this));
        m_oneShots.last()->start(ms);
    }

    /// Deliver the thread's posted events until none is left (a chain of queued calls runs
    /// to its end); the clock stands still meanwhile.
    static void settle()
    {
        EventCounter counter;
        QCoreApplication::instance()->installEventFilter(&counter);
        constexpr int kMaxRounds = 100000;
        int round = 0;
        for (; round < kMaxRounds; ++round) {
            counter.count = 0;
            QCoreApplication::processEvents(QEventLoop::AllEvents);
            QCoreApplication::sendPostedEvents();
            if (counter.count == 0)
                break;
        }
        QCoreApplication::instance()->removeEventFilter(&counter);
        if (round == kMaxRounds)
            qWarning("ManualTimers::settle: events keep coming while the clock stands still");
    }

    /// Advance the clock by `ms`, firing every timer due on the way in due order.
    void advance(double ms)
    {
        const qint64 targetNs = m_clock->nowNs() + qint64(ms * 1e6);
        settle();
        while (fireNextDue(targetNs))
            settle();
        m_clock->setNs(targetNs);
        settle();
    }

    /// Advance timer by timer until `done()` holds; false if it still does not after `limitMs`
    /// on the clock (the hand-run QTRY_VERIFY_WITH_TIMEOUT).
    bool advanceUntil(const std::function<bool()> &done, double limitMs = 60000)
    {
        const qint64 limitNs = m_clock->nowNs() + qint64(limitMs * 1e6);
        settle();
        while (!done()) {
            if (!fireNextDue(limitNs))
                return false;
            settle();
        }
        return true;
    }

private:
    class Timer final : public bus::SingleShotTimer {
    public:
        Timer(std::shared_ptr<State> state, ManualTimers *owner)
            : m_state(std::move(state)), m_owner(owner)
        {
        }
        ~Timer() override { m_state->active = false; }
        void start(int ms) override
        {
            m_state->active = true;
            m_state->lastMs = ms;
            ++m_state->starts;
            m_state->order = ++m_owner->m_starts;
            if (m_owner->m_clock)
                m_state->dueNs = m_owner->m_clock->nowNs() + qint64(ms) * 1'000'000;
        }
        void stop() override { m_state->active = false; }
        bool isActive() const override { return m_state->active; }

    private:
        std::shared_ptr<State> m_state;
        ManualTimers *m_owner;
    };

    /// Counts the events delivered on this thread (an application-wide filter sees them all).
    struct EventCounter : QObject {
        int count = 0;
        bool eventFilter(QObject *, QEvent *) override
        {
            ++count;
            return false;
        }
    };

    /// Fire the earliest active timer due no later than `limitNs`, the clock set to its due
    /// time; false if there is none.
    bool fireNextDue(qint64 limitNs)
    {
        int next = -1;
        for (int i = 0; i < m_timers.size(); ++i) {
            const State &s = *m_timers.at(i);
            if (!s.active || s.dueNs > limitNs)
                continue;
            const State *best = next < 0 ? nullptr : m_timers.at(next).get();
            if (!best || s.dueNs < best->dueNs || (s.dueNs == best->dueNs && s.order < best->order))
                next = i;
        }
        if (next < 0)
            return false;
        m_clock->setNs(m_timers.at(next)->dueNs);
        return fire(next);
    }

    std::shared_ptr<ManualClock> m_clock;
    QVector<std::shared_ptr<State>> m_timers;
    QVector<std::shared_ptr<Timer>> m_oneShots; ///< singleShot()'s, owned here
    quint64 m_starts = 0;
};

} // namespace lk::testsupport
