#include "RecordingDecode.h"

#include "Console.h"
#include "Subcommand.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/Command.h>
#include <protocol/FieldJson.h>
#include <protocol/Request.h>
#include <recording/RecordTraffic.h>
#include <recording/RecordedFrameParser.h>
#include <recording/RecordingReader.h>

#include <QtCore/QFile>

namespace lk::lkctl {

using recording::RecordedFrame;
using recording::RecordEvent;

namespace {

QString noteText(const RecordEvent &r)
{
    // The Traffic view's wording, one record at a time.
    const auto notes = recording::trafficEventsOf({r}, {});
    return notes.isEmpty() ? QString() : notes.first().text;
}

QString canIdText(quint32 canId)
{
    return QStringLiteral("0x") +
           QString::number(canId, 16).toUpper().rightJustified(3, QLatin1Char('0'));
}

/// A multi-motor torque frame (0x280, docs/CAN.md section 4.2), sent or heard: the torque of
/// each of IDs 1..4, an empty slot's 0 A too.
QJsonObject multiTorqueObject(const protocol::ParseEvent &e)
{
    const std::optional<protocol::CanRecord> record = protocol::CanRecord::decode(e.bytes);
    const auto iq =
        record ? protocol::can::decodeMultiMotorTorque(record->canData()) : std::nullopt;
    if (!iq)
        return protocol::FieldJson::errorObject(protocol::ParseError::BadLength, e.bytes);
    QJsonObject fields;
    for (size_t i = 0; i < iq->size(); ++i)
        fields.insert(QStringLiteral("iq_a_%1").arg(i + 1),
                      (*iq)[i] * protocol::kIqCommandAmpsPerLsb);
    return {{QStringLiteral("direction"),
             QLatin1String(protocol::directionName(protocol::FrameDirection::Request))},
            {QStringLiteral("command"), QStringLiteral("multi_torque")},
            {QStringLiteral("can_id"), canIdText(protocol::can::kMultiMotorId)},
            {QStringLiteral("fields"), fields}};
}

/// The CLI.md object of a recorded frame or fault; a CAN frame also names its "can_id".
QJsonObject objectOf(const RecordedFrame &f)
{
    using protocol::FieldJson;
    const protocol::ParseEvent &e = f.event;
    if (e.isFrame && e.canId == protocol::can::kMultiMotorId)
        return multiTorqueObject(e);
    if (!e.isFrame || !f.context.onCan() || e.direction == protocol::FrameDirection::Reply) {
        QJsonObject o = FieldJson::eventObject(e, f.context);
        if (e.canId)
            o.insert(QStringLiteral("can_id"), canIdText(*e.canId));
        return o;
    }
    // A CAN request's B1..B7 decode with the CAN layouts of its drive's generation
    // (FieldJson::frameObject reads a request's data with RS485's).
    const protocol::RequestDecodeResult r = protocol::decodeRequest(e.frame, f.context);
    if (!r.request)
        return FieldJson::errorObject(protocol::ParseError::BadLength, e.bytes);
    QJsonObject o{
        {QStringLiteral("direction"), QLatin1String(protocol::directionName(e.direction))},
        {QStringLiteral("command"), protocol::CommandTable::name(r.request->command)},
        {QStringLiteral("code"), protocol::CommandTable::codeText(e.frame.command)},
        {QStringLiteral("id"), int(e.frame.id)},
        {QStringLiteral("fields"), FieldJson::requestFields(*r.request, f.context)}};
    if (e.canId)
        o.insert(QStringLiteral("can_id"), canIdText(*e.canId));
    return o;
}

} // namespace

QByteArray recordTimeText(qint64 timeNs)
{
    // Integer microseconds, rounded half away from zero: exact, where ns * 1e-9 as a double
    // printed at its shortest gives 0.00030000000000000003.
    const qint64 magnitude = timeNs < 0 ? -timeNs : timeNs;
    const qint64 us = (magnitude + 500) / 1000;
    QByteArray text = QByteArray::number(us / 1000000) + '.' +
                      QByteArray::number(us % 1000000).rightJustified(6, '0');
    return timeNs < 0 && us > 0 ? '-' + text : text;
}

QByteArray timedJsonLine(const QJsonObject &object, qint64 timeNs, const char *wire)
{
    // time_s and wire sort after every key an event or note object has: appended, they keep
    // the order toJsonLine gives the rest.
    QByteArray line = protocol::FieldJson::toJsonLine(object);
    line.chop(1);
    if (line.size() > 1)
        line += ',';
    line += "\"time_s\":" + recordTimeText(timeNs);
    if (wire)
        line += QByteArray(",\"wire\":\"") + wire + '"';
    return line + "}\n";
}

bool isRecordingFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && recording::RecordingReader::hasMagic(f.read(8));
}

int decodeRecording(recording::RecordingReader &reader, Console &console)
{
    bool sawFault = false;
    recording::RecordedFrameParser parser(reader.header().context,
                                          recording::linkOf(reader.header()));
    const auto sink = [&](const RecordedFrame &f) {
        const QJsonObject o = objectOf(f);
        sawFault = sawFault || protocol::FieldJson::isError(o);
        console.out(timedJsonLine(o, f.timeNs, f.transmitted ? "tx" : "rx"));
    };
    RecordEvent e;
    while (reader.next(&e)) {
        parser.feed(e, sink);
        if (e.kind == RecordEvent::Kind::Link || e.kind == RecordEvent::Kind::Dropped) {
            console.out(timedJsonLine({{QStringLiteral("note"), noteText(e)}}, e.timeNs));
        }
    }
    parser.finish(sink);
    console.flush();
    if (reader.error().isError()) {
        console.errLine(QStringLiteral("lkctl decode: %1").arg(reader.error().message));
        return kExitBadData;
    }
    return sawFault ? kExitBadData : kExitOk;
}

} // namespace lk::lkctl
