#pragma once

#include <QtCore/QHash>
#include <QtCore/QVector>

#include <optional>

namespace lk::recording {

/// Decides from session events when the black box should be saved: an emergency stop, a
/// fault flag a drive did not have before, the link lost, or a burst of timeouts. Pure and
/// clocked by its callers (session nanoseconds), so it is tested without a GUI or a bus; the
/// GUI wires it to BusSession's signals and calls BlackBox::saveLast on a "save now".
class BlackBoxTriggers {
public:
    enum class Reason { EmergencyStop, FaultFlag, LinkLost, TimeoutBurst };

    struct Settings {
        int timeoutBurstCount = 5;             ///< this many timeouts ...
        qint64 timeoutBurstNs = 2'000'000'000; ///< ... within this time is a burst
        qint64 holdoffNs = 30'000'000'000;     ///< after a save, no other save this long
    };

    BlackBoxTriggers() = default;
    explicit BlackBoxTriggers(Settings settings) : m_settings(settings) {}

    /// Each returns the reason to save now, or nullopt. An emergency stop always saves;
    /// the others are held off for `holdoffNs` after any save, so one incident saves once.
    std::optional<Reason> emergencyStop(qint64 ns);
    /// A drive's current error flags (bits as read_state1 reports them): saves when a bit
    /// is set that was clear in the last report of that drive (the first report counts).
    std::optional<Reason> faultFlags(int id, quint32 flags, qint64 ns);
    std::optional<Reason> linkLost(qint64 ns);
    std::optional<Reason> timeout(qint64 ns);

private:
    std::optional<Reason> fire(Reason reason, qint64 ns);

    Settings m_settings;
    QHash<int, quint32> m_flags;
    QVector<qint64> m_timeouts; ///< times of the recent timeouts
    std::optional<qint64> m_lastSaveNs;
};

/// "emergency stop", "fault flag", "link lost", "timeout burst": for file names and logs.
const char *blackBoxReasonName(BlackBoxTriggers::Reason reason);

} // namespace lk::recording
