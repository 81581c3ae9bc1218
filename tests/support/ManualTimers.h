#pragma once

#include <bus/SingleShotTimer.h>

#include <QtCore/QVector>

#include <functional>
#include <memory>

namespace lk::testsupport {

/// Timers a test fires by hand: a SingleShotTimerFactory whose timers record when they were
/// started and for how long, and time out only when the test says so.
class ManualTimers {
public:
    /// One timer as the object under test sees it, and the handle the test keeps.
    struct State {
        std::function<void()> onTimeout;
        bool active = false;
        int lastMs = -1; ///< the interval of the last start(); -1: never started
        int starts = 0;
    };

    bus::SingleShotTimerFactory factory()
    {
        return [this](QObject *, std::function<void()> onTimeout) {
            auto state = std::make_shared<State>();
            state->onTimeout = std::move(onTimeout);
            m_timers.append(state);
            return std::unique_ptr<bus::SingleShotTimer>(new Timer(state));
        };
    }

    int count() const { return int(m_timers.size()); }
    const State &at(int i) const { return *m_timers.at(i); }
    /// Time out timer `i` if it is running (as its interval passing would); false if it was
    /// not.
    bool fire(int i = 0)
    {
        State &s = *m_timers.at(i);
        if (!s.active)
            return false;
        s.active = false;
        s.onTimeout();
        return true;
    }

private:
    class Timer final : public bus::SingleShotTimer {
    public:
        explicit Timer(std::shared_ptr<State> state) : m_state(std::move(state)) {}
        ~Timer() override { m_state->active = false; }
        void start(int ms) override
        {
            m_state->active = true;
            m_state->lastMs = ms;
            ++m_state->starts;
        }
        void stop() override { m_state->active = false; }
        bool isActive() const override { return m_state->active; }

    private:
        std::shared_ptr<State> m_state;
    };

    QVector<std::shared_ptr<State>> m_timers;
};

} // namespace lk::testsupport
