#pragma once

#include "SimBus.h"

#include "protocol/CanLayout.h"
#include "protocol/CanRecordParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QHash>
#include <QtCore/QList>
#include <QtCore/QSet>

#include <optional>

namespace lk::sim {

/// Counters of a SimCanFront.
struct SimCanCounters {
    qint64 requests = 0; ///< drive frames read as requests
    qint64 replies = 0;  ///< records sent back
    qint64 faults = 0;   ///< records that were not frames (garbage, bad DLC, unknown B0)
    /// frames that are no request of the drive's dialect: another node's replies on 0x140+ID
    qint64 notRequests = 0;
    qint64 unanswered = 0;  ///< absent IDs, commands the drive lacks on CAN
    qint64 otherFrames = 0; ///< frames of no drive (0x280 included) and error frames
};

/// The CAN face of a SimBus: CAN records (protocol/CanRecord.h) in, the addressed drive's own
/// typed handling (SimDrive::handle), CAN records out. Only requests are answered: a frame on
/// 0x140+ID whose bytes are no request's layout of the drive's dialect (another node's reply
/// of the old generation, which shares the ID) and every frame on 0x180+ID are ignored. An
/// echo command's reply repeats its request byte for byte: such a frame of another node is
/// taken as a request (nothing can tell). A drive of generation V2_3 is an old
/// CAN drive, V2_35 a V2.36 one; both keep their physics and faults. A CAN drive never
/// answers what its generation lacks on CAN (0x12, 0x93, 0x40..0x44), and an old drive echoes
/// 0x95 without changing its angle (docs/CAN.md section 9). Old drives 1..4 take the 0x280
/// multi-motor torque frame (section 5). Replies go out on the documented
/// ID of the drive's generation unless setReplyBase() says otherwise. Not thread-safe; time is
/// the caller's, as for SimBus.
class SimCanFront {
public:
    explicit SimCanFront(SimBus &bus);

    /// Host records in; reply records out, in order. Advances the bus to nowSeconds first.
    QList<SimReply> receive(const QByteArray &records, double nowSeconds);
    /// Whether old drive `id` (1..4) is in the multi-motor ("broadcast") mode the vendor tool
    /// sets: such a drive takes its iq from the 0x280 frame and answers on its own ID. On by
    /// default; V2.36 drives never answer 0x280 (undocumented there).
    void setMultiMotorMode(int id, bool on);
    /// Answer on 0x140+ID or 0x180+ID whatever the generation (nullopt: as documented).
    void setReplyBase(std::optional<protocol::can::IdBase> base) { m_replyBase = base; }
    const SimCanCounters &counters() const { return m_counters; }
    /// The context a drive of the bus is read with on CAN.
    static protocol::DecodeContext contextOf(const SimDrive &drive);

private:
    void onEvent(const protocol::ParseEvent &event, QList<SimReply> &out);
    void answer(SimDrive &drive, const protocol::Request &request, QList<SimReply> &out);
    void answerMultiMotor(const protocol::can::CanData &data, QList<SimReply> &out);
    /// CAN V2.36's 0x95 with an angle other than 0; false when `frame` is not one.
    bool answerSetPosition(SimDrive &drive, const protocol::Frame &frame,
                           const protocol::DecodeContext &context, QList<SimReply> &out);
    /// The ID a reply of drive `id` goes out on: the generation's, or the one chosen.
    quint32 replyId(quint8 id, const protocol::DecodeContext &context) const;
    static bool isRequestLayout(const protocol::Request &request, const protocol::Frame &frame,
                                const protocol::DecodeContext &context);

    SimBus &m_bus;
    protocol::CanRecordParser m_parser{protocol::LinkEnd::Drive};
    std::optional<protocol::can::IdBase> m_replyBase;
    SimCanCounters m_counters;
    QSet<int> m_multiMotorOff;        ///< old drives 1..4 not in the multi-motor mode
    QList<SimReply> *m_out = nullptr; ///< the replies of the receive() under way
};

} // namespace lk::sim
