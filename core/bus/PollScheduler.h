#pragma once

#include "BusTiming.h"
#include "LinkTiming.h"

#include "PollPlan.h"
#include "UnansweredPolls.h"

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QVector>

#include <functional>
#include <optional>

namespace lk::bus {

/// Round robin over (ID, command) entries of a PollPlan. Pulled by the BusWorker whenever the
/// bus is idle, so polls fill the gaps between operator requests. A slot is never handed out
/// while its previous poll is outstanding; a cycle starts at most every 1/rateHz seconds.
/// A plan with a focus runs two round robins: the focus drive's, back to back, and the other
/// drives' (rate-limited as before), one of whose polls follows every focusOthersEvery focus
/// polls. A drive's extra commands follow its `commands` in its round.
/// Besides the plan, the drives the speed watch names (setWatched) have their read_state2 due
/// at all times: one watch poll, then one of the plan's when one is due, and watch polls back
/// to back while none is, whatever the plan's rate (docs/SUPERVISION.md).
class PollScheduler {
public:
    /// Series of an ID, to skip commands the series does not answer (0x9D on MS).
    using SeriesLookup = std::function<std::optional<protocol::Series>(int id)>;

    void setSeriesLookup(SeriesLookup lookup) { m_series = std::move(lookup); }
    /// Replace the plan; non-read commands and IDs outside 1..32 are dropped, and so are the
    /// extra commands of an ID that its `commands` poll already.
    void setPlan(const PollPlan &plan, double now);
    void clear();          ///< forgets the plan; the watched drives stay
    bool isActive() const; ///< a plan with something to poll
    const PollPlan &plan() const { return m_plan; }
    /// The drives whose speed the speed watch reads as often as the bus allows (SpeedWatch):
    /// read_state2 of each, in turn, independent of the plan (set, cleared or rate-limited).
    void setWatched(const QVector<int> &ids);
    QVector<int> watched() const;
    bool hasWork() const { return isActive() || !m_watch.entries.isEmpty(); }
    /// The next watch poll only (the plan is held, e.g. while its link is suspended).
    std::optional<protocol::Request> nextWatch();
    /// The poll last handed out was a watch poll (it belongs to no round of the plan).
    bool lastWasWatch() const { return m_lastWasWatch; }

    /// The poll to send now, or nullopt (nothing due, or everything outstanding).
    std::optional<protocol::Request> next(double now);
    /// When next() may return a poll again (now when one is due; +inf when none will be).
    double nextDueTime(double now) const;
    /// The poll for (id, command) ended (any status); its slot may be handed out again.
    void completed(int id, protocol::Command command);
    /// The drive answered that poll, or it timed out: a command some series lack, left
    /// unanswered by a drive of unknown series while it answers its other polls, is polled no
    /// more (UnansweredPolls). True when this result stopped it. clear() polls it again.
    bool noteAnswer(int id, protocol::Command command, bool answered);
    bool isMuted(int id, protocol::Command command) const
    {
        return m_unanswered.isMuted(id, command);
    }
    int outstanding() const;
    /// The round the poll last handed out by next() belongs to (after setPlan(): the plan's
    /// first round): 1 for the first round of the first plan, +1 for every new round and
    /// every new plan (never reused, never 0). With a focus, the focus drive's rounds and the
    /// other drives' rounds are numbered apart, from the same counter.
    quint64 cycle() const { return m_current.round; }
    /// When that round began (the clock next() and setPlan() are given).
    double cycleStart() const { return m_current.start; }
    /// The bus limit, in transactions/s, for the plan's command mix at `baud` with the
    /// drives' turnaround `turnaroundS` (the formula's 0.5 ms until one was measured).
    double busLimitPerSecond(int baud, double turnaroundS = BusTiming::kTurnaroundS) const;
    /// Full rounds per second at that limit (every polled command of every ID once).
    double cycleLimitHz(int baud, double turnaroundS = BusTiming::kTurnaroundS) const;
    /// The same on any link (CAN: its frames; `turnaroundS` the drives' reply time).
    double busLimitPerSecond(const LinkTiming &timing, double turnaroundS) const;
    double cycleLimitHz(const LinkTiming &timing, double turnaroundS) const;

    static bool isPollable(protocol::Command command);

private:
    struct Slot {
        int id = 0;
        protocol::Command command = protocol::Command::ReadState2;
        bool outstanding = false;
    };
    struct Round {
        quint64 round = 0;
        double start = 0;
    };
    /// One round robin: the whole plan without a focus; with one, the focus drive's entries
    /// (m_main) and the other drives' (m_others).
    struct Ring {
        QVector<Slot> entries;
        int cursor = 0;
        double rateHz = 0; ///< rounds per second at most; 0: as fast as the bus allows
        Round current;
    };
    /// plan.extraCommands for valid IDs, read commands only, without what `commands` polls.
    QMap<int, QVector<protocol::Command>>
    extrasOf(const QMap<int, QVector<protocol::Command>> &extras) const;
    QVector<int> polledIds() const;                      ///< `ids`, then IDs with extras only
    QVector<protocol::Command> commandsOf(int id) const; ///< one round of `id` (no focus)
    bool skipped(const Slot &slot) const;
    bool eligible(const Slot &slot) const;
    bool pollable(const Ring &ring) const; ///< some slot the series answers
    bool othersTurn() const;
    double dueTime(const Ring &ring, double now) const;
    std::optional<protocol::Request> take(Ring &ring, double now);
    std::optional<protocol::Request> nextOfPlan(double now);
    /// The commands of one repeating stretch of polls and how many focus (or plain) rounds
    /// it holds: what the bus limit is computed from.
    QVector<protocol::Command> pollMix(int *rounds) const;

    PollPlan m_plan;
    SeriesLookup m_series;
    UnansweredPolls m_unanswered;
    Ring m_main;
    Ring m_others;
    Ring m_watch;                ///< read_state2 of each watched drive; no rounds, no rate
    bool m_lastWasWatch = false; ///< watch and plan polls alternate
    int m_sinceOthers = 0;       ///< focus polls handed out since the last poll of another drive
    quint64 m_rounds = 0;        ///< round numbers given out so far
    Round m_current;
};

} // namespace lk::bus
