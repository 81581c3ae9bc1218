#pragma once

#include "KnownMotor.h"
#include "StopTargets.h"

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QSet>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {

/// The IDs a bus knows (scan, setSeries, any reply) and how to decode each one's replies.
/// Mutators return whether anything changed, so the owner signals only real changes.
///
/// Apart from what it knows, it remembers which IDs answered on this connection and which
/// were last seen moving: a scan forgets the first (forget()), never the others, so that an
/// emergency stop during a re-scan reaches the drives it just saw turning first.
class MotorRegistry {
public:
    const KnownMotors &all() const { return m_motors; }
    std::optional<protocol::Series> series(int id) const;
    /// Series, generation and link for the decoder; unknown IDs decode as MF (iq), V2.3.
    protocol::DecodeContext decodeContext(int id) const;
    /// The link the drives are reached over (BusWorker sets it when a transport opens).
    void setLink(protocol::Link link) { m_link = link; }
    protocol::Link link() const { return m_link; }

    /// Who an emergency stop must reach: `ids` (the caller's known and recently commanded
    /// drives) and the drives seen moving, then every known ID and every ID that answered on
    /// this connection, then every other ID of 1..32: always all 32.
    StopTargets emergencyTargets(const QVector<int> &ids) const;
    /// Why `request` must not be sent: its drive's generation lacks the command (known once
    /// the drive's model was read). nullopt: it may go.
    std::optional<QString> unavailableReason(const protocol::Request &request) const;

    /// `id` answered: it is known (true when it was not) and remembered as answering.
    bool noteSeen(int id);
    /// Whether `id` is moving as far as the bus saw: a motion command it acknowledged or a
    /// speed it reported.
    void noteMotion(int id, bool moving);
    /// IDs that answered on this connection, whatever a scan has forgotten since.
    const QSet<int> &answered() const { return m_answered; }
    bool setSeries(int id, protocol::Series series);
    /// The drive's model and generation; its series is `series`, or else what the model's
    /// names tell (seriesOf()), wherever the model was read (a scan, lkctl info, a view).
    bool learnModel(int id, const protocol::ModelInfo &model,
                    std::optional<protocol::Series> series);
    /// `id` answered a command only `generation` has: its generation, unless its model (the
    /// surer word) was read. Makes `id` known.
    bool learnGeneration(int id, protocol::Generation generation);
    bool forget(int firstId, int lastId);
    /// The user's word on drive `id` (CAN and listen-only have no model read): series,
    /// generation and, when given, gear ratio. Makes `id` known; no reply overrides it.
    bool setIdentity(int id, protocol::Series series, protocol::Generation generation,
                     std::optional<double> gearRatio);
    /// A CAN reply told `id`'s generation (docs/CAN.md section 9): taken unless the user
    /// chose one or the model was read. Makes `id` known.
    bool learnCanGeneration(int id, protocol::Generation generation);

    /// The series a model's names tell: the motor's ("MS5005"), else the driver's; nullopt
    /// when neither does.
    static std::optional<protocol::Series> seriesOf(const protocol::ModelInfo &model);

private:
    KnownMotors m_motors;
    QSet<int> m_answered;
    QSet<int> m_moving;
    protocol::Link m_link = protocol::Link::Rs485;
};

} // namespace lk::bus
