#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QRandomGenerator>
#include <QtCore/QSet>
#include <QtCore/QString>

#include <array>
#include <atomic>

namespace lk::sim {

/// Kinds of bus fault the simulator can inject into its replies.
enum class Fault {
    DropReply,    ///< the drive acts on the request but its reply is lost
    CorruptReply, ///< one data byte flipped: bad data checksum (bad header checksum if LEN 0)
    WrongLength,  ///< reply one data byte short with consistent checksums: bad_length
    Garbage,      ///< 1..8 noise bytes (never 0x3E) before the reply
    ExtraDelay,   ///< the reply comes extraDelaySeconds() late
    SilencedId,   ///< counted when a request to a silenced ID is swallowed
    /// Firmware 2.35's bug (docs/V2.35.md section 12): a 0xA4 reply whose data checksum is off by
    /// 3 while the header is good. SimBus applies it to V2.35 drives' 0xA4 replies only.
    FirmwareChecksum,
};
constexpr int kFaultKinds = 7;

/// Seeded, deterministic fault injection for SimBus: per-reply probabilities, one-shot
/// counts ("the next 3 replies are dropped"), silenced IDs and a disconnect flag for the
/// transport. Everything but the disconnect flag belongs to the bus thread; the flag may be
/// raised from any thread.
class FaultInjector {
public:
    explicit FaultInjector(quint32 seed = 1);

    void setSeed(quint32 seed) { m_rng.seed(seed); }
    /// Chance 0..1 that each reply gets this fault (SilencedId has no probability).
    void setProbability(Fault fault, double probability);
    double probability(Fault fault) const { return m_probability[index(fault)]; }
    /// The next `count` replies get this fault for sure (adds to any pending count).
    void injectNext(Fault fault, int count = 1);
    int pending(Fault fault) const { return m_oneShot[index(fault)]; }
    /// The next `count` replies to `command` from drive `id` (0: from any drive) are lost, whatever
    /// else the bus answers in between. A test aims a drop at one request this way: a plain
    /// injectNext() meets whichever reply comes first, and under load that order changes.
    void dropNextRepliesTo(quint8 command, int id, int count = 1);
    /// Aimed drops not yet spent, over every command and drive.
    int pendingAimedDrops() const;
    void setExtraDelaySeconds(double seconds) { m_extraDelay = seconds; }
    double extraDelaySeconds() const { return m_extraDelay; }

    /// A silenced drive neither acts on requests nor answers, as if cut off the bus.
    void setSilenced(int id, bool silenced);
    bool isSilenced(int id) const { return m_silenced.contains(id); }

    /// Ask the transport to report an unplugged link (safe from any thread).
    void requestDisconnect() { m_disconnect.store(true); }
    bool disconnectRequested() const { return m_disconnect.load(); }
    /// Read and clear the flag (the transport calls this).
    bool takeDisconnect() { return m_disconnect.exchange(false); }

    /// How often each fault was applied since the last resetCounts().
    int injectedCount(Fault fault) const { return m_count[index(fault)]; }
    void resetCounts() { m_count.fill(0); }
    /// All probabilities, one-shots, silenced IDs and the extra delay back to none.
    void clear();
    bool active() const;

    /// Configure from text, e.g. "drop=0.01,corrupt=0.02,length=0.01,garbage=0.05,
    /// delay=0.1,delay_ms=5,silent=3,silent=7,seed=42". False with a message on bad input
    /// (nothing is changed then).
    bool configure(const QString &spec, QString *error = nullptr);

    /// SimBus side: note a swallowed request to a silenced ID.
    void countSilenced() { ++m_count[index(Fault::SilencedId)]; }
    /// SimBus side: maybe spoil the data checksum of a V2.35 drive's 0xA4 reply by +-3, as
    /// real fw 2.35 does (Fault::FirmwareChecksum). True when it did.
    bool applyFirmwareChecksumBug(QByteArray &reply);
    /// SimBus side: apply faults to one encoded reply. Returns false when it is dropped;
    /// otherwise may change the bytes and add to extraDelay.
    bool apply(QByteArray &reply, double &extraDelay);

private:
    static int index(Fault f) { return static_cast<int>(f); }
    bool fires(Fault fault);
    void corrupt(QByteArray &reply);
    void shorten(QByteArray &reply);
    QByteArray garbage();
    bool firesAimedDrop(const QByteArray &reply);

    struct AimedDrop {
        quint8 command;
        int id;
        int count;
    };
    QRandomGenerator m_rng;
    std::array<double, kFaultKinds> m_probability{};
    std::array<int, kFaultKinds> m_oneShot{};
    std::array<int, kFaultKinds> m_count{};
    QList<AimedDrop> m_aimedDrops;
    double m_extraDelay = 0.005;
    QSet<int> m_silenced;
    std::atomic<bool> m_disconnect{false};
};

} // namespace lk::sim
