#include "SimCanFront.h"

#include "protocol/CanRecord.h"

namespace lk::sim {

SimCanFront::SimCanFront(SimBus &bus) : m_bus(bus)
{
    const auto other = [this](const protocol::CanRecord &) { ++m_counters.otherFrames; };
    m_parser.setErrorFrameSink(other);
    m_parser.setOtherFrameSink([this](const protocol::CanRecord &record) {
        ++m_counters.otherFrames;
        if (m_out && !record.isEcho() && !record.isError() && !record.isExtended() &&
            record.canId == protocol::can::kMultiMotorId)
            answerMultiMotor(record.canData(), *m_out);
    });
}

void SimCanFront::setMultiMotorMode(int id, bool on)
{
    if (on)
        m_multiMotorOff.remove(id);
    else
        m_multiMotorOff.insert(id);
}

void SimCanFront::answerMultiMotor(const protocol::can::CanData &data, QList<SimReply> &out)
{
    const auto iq = protocol::can::decodeMultiMotorTorque(data);
    if (!iq)
        return;
    // Drives 1..4 answer in ascending ID order, each on its own ID with a motion reply, as an
    // old drive answers 0xA1 (docs/CAN.md section 5). V2.36 documents no multi-motor frame and
    // a drive not in the mode ignores it: both stay silent.
    for (int id = 1; id <= protocol::can::kMultiMotorDrives; ++id) {
        SimDrive *drive = m_bus.drive(id);
        if (!drive || drive->generation() != protocol::Generation::V2_3 ||
            m_multiMotorOff.contains(id))
            continue;
        if (m_bus.faults().isSilenced(id)) {
            m_bus.faults().countSilenced();
            continue;
        }
        ++m_counters.requests;
        m_bus.countRequest(id, protocol::Command::Torque);
        protocol::TorqueCommand torque;
        torque.iqRaw = (*iq)[static_cast<size_t>(id - 1)];
        answer(*drive, protocol::Request{protocol::Command::Torque, quint8(id), torque}, out);
    }
}

protocol::DecodeContext SimCanFront::contextOf(const SimDrive &drive)
{
    return protocol::DecodeContext{drive.series(), drive.generation(), protocol::Link::Can};
}

quint32 SimCanFront::replyId(quint8 id, const protocol::DecodeContext &context) const
{
    if (!m_replyBase)
        return protocol::can::replyCanId(id, context.generation);
    return (*m_replyBase == protocol::can::IdBase::Base180 ? protocol::can::kReplyBaseV236
                                                           : protocol::can::kRequestBase) +
           id;
}

QList<SimReply> SimCanFront::receive(const QByteArray &records, double nowSeconds)
{
    m_bus.advanceTo(nowSeconds);
    QList<SimReply> out;
    m_out = &out; // for the multi-motor frame, which reaches the other-frame sink
    m_parser.feed(records, [&](const protocol::ParseEvent &e) { onEvent(e, out); });
    m_out = nullptr;
    return out;
}

void SimCanFront::onEvent(const protocol::ParseEvent &event, QList<SimReply> &out)
{
    if (!event.isFrame) {
        ++m_counters.faults;
        return;
    }
    if (event.direction != protocol::FrameDirection::Request)
        return; // another drive's reply on 0x180+ID: not for us
    SimDrive *drive = m_bus.drive(event.frame.id);
    if (!drive) {
        ++m_counters.unanswered;
        return;
    }
    if (m_bus.faults().isSilenced(drive->id())) {
        m_bus.faults().countSilenced();
        return;
    }
    const protocol::DecodeContext ctx = contextOf(*drive);
    if (answerSetPosition(*drive, event.frame, ctx, out))
        return;
    // The old generation lacks a working 0x95 but still echoes it: answer() does so.
    const bool oldClearAngle = event.frame.command == quint8(protocol::Command::ClearAngle) &&
                               ctx.generation == protocol::Generation::V2_3;
    const protocol::RequestDecodeResult decoded =
        oldClearAngle ? protocol::RequestDecodeResult{protocol::Request{
                            protocol::Command::ClearAngle, event.frame.id, protocol::NoPayload{}}}
                      : protocol::decodeRequest(event.frame, ctx);
    if (!decoded.request) {
        // Commands the drive's CAN generation lacks decode as unknown: the drive is silent.
        if (decoded.error == protocol::DecodeError::UnknownCommand)
            ++m_counters.unanswered;
        else
            ++m_counters.notRequests;
        return;
    }
    if (!oldClearAngle && !isRequestLayout(*decoded.request, event.frame, ctx)) {
        ++m_counters.notRequests; // another node's reply on the shared 0x140+ID
        return;
    }
    ++m_counters.requests;
    m_bus.countRequest(decoded.request->id, decoded.request->command);
    answer(*drive, *decoded.request, out);
}

bool SimCanFront::answerSetPosition(SimDrive &drive, const protocol::Frame &frame,
                                    const protocol::DecodeContext &context, QList<SimReply> &out)
{
    // CAN V2.36's 0x95 sets the current position to any angle (RAM) and echoes the frame
    // whole; the common path's reply (acknowledged) would carry zeros. An angle of 0 takes
    // the common path: clear_angle, with its firmware quirks.
    if (frame.command != quint8(protocol::Command::ClearAngle) ||
        context.generation != protocol::Generation::V2_35)
        return false;
    const protocol::can::CanData data{protocol::can::requestCanId(frame.id),
                                      protocol::can::bytesOf(frame)};
    const std::optional<qint32> angle = protocol::can::decodeSetPosition(data);
    if (!angle || *angle == 0)
        return false;
    ++m_counters.requests;
    m_bus.countRequest(frame.id, protocol::Command::ClearAngle);
    drive.setMultiTurnAngle(*angle);
    SimReply r; // the echo, on the reply ID
    r.bytes =
        protocol::CanRecord::of(protocol::can::CanData{replyId(frame.id, context), data.bytes})
            .encode();
    r.delaySeconds = m_bus.replyDelay();
    r.id = frame.id;
    r.command = protocol::Command::ClearAngle;
    ++m_counters.replies;
    out.append(r);
    return true;
}

bool SimCanFront::isRequestLayout(const protocol::Request &request, const protocol::Frame &frame,
                                  const protocol::DecodeContext &context)
{
    // A reply of the old generation travels on the request's own ID, and most of its layouts
    // decode as a request too; encoded back, a request gives its own bytes, a reply (a read's
    // temperature where a request has zeros) does not. Where the codec will not encode what
    // it decoded, nothing tells: it is taken as a request.
    const protocol::can::CanEncodeResult encoded = protocol::can::encodeRequest(request, context);
    return !encoded.data || encoded.data->bytes == protocol::can::bytesOf(frame);
}

void SimCanFront::answer(SimDrive &drive, const protocol::Request &request, QList<SimReply> &out)
{
    const protocol::DecodeContext ctx = contextOf(drive);
    std::optional<protocol::can::CanData> data;
    if (request.command == protocol::Command::ClearAngle &&
        ctx.generation == protocol::Generation::V2_3) {
        // "Not implemented" on the old generation: the echo comes, the angle stays.
        data = protocol::can::CanData{protocol::can::replyCanId(request.id, ctx.generation),
                                      protocol::can::encodeSetPosition(request.id, 0).bytes};
    } else if (protocol::CommandTable::availableOn(request.command, ctx)) {
        // On CAN every generation's 0x19 reply carries the zero that was set (docs/CAN.md).
        if (request.command == protocol::Command::WriteZeroRom)
            drive.setZeroReplyCarriesOffset(true);
        if (const std::optional<protocol::Reply> reply = drive.handle(request)) {
            const protocol::can::CanEncodeResult encoded = protocol::can::encodeReply(*reply, ctx);
            data = encoded.data;
            // CAN V2.36 has no 0x93: its 0x80 clears the turn count too (docs/CAN.md).
            if (request.command == protocol::Command::MotorOff &&
                ctx.generation == protocol::Generation::V2_35)
                drive.clearTurnCount();
        }
    }
    if (!data) {
        ++m_counters.unanswered;
        return;
    }
    data->canId = replyId(request.id, ctx);
    SimReply r;
    r.bytes = protocol::CanRecord::of(*data).encode();
    r.delaySeconds = m_bus.replyDelay();
    r.id = request.id;
    r.command = request.command;
    ++m_counters.replies;
    out.append(r);
}

} // namespace lk::sim
